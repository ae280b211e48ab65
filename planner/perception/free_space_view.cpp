#include "planner/perception/free_space_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ifar::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Azimuth bins of 0.4 degrees: a VLP-16 fires every 0.2 degrees at 10 Hz (0.4 at 20 Hz), so each bin holds
// a firing of all 16 lasers; an empty bin (no return) is never seen through.
constexpr double kBinRad = 0.4 * kPi / 180.0;
const std::size_t kBins = static_cast<std::size_t>(std::ceil(2.0 * kPi / kBinRad));

/// atan2 to within 0.0015 rad (a tenth of a bin): one per return, and the bins need no more. The view
/// bins its rays and the cells it is asked about with this same function.
double fastAtan2(double y, double x)
{
  const double absolute_x = std::abs(x);
  const double absolute_y = std::abs(y);
  const double larger = std::max(absolute_x, absolute_y);
  if (!(larger > 0.0)) {
    return 0.0;
  }
  const double ratio = std::min(absolute_x, absolute_y) / larger;
  const double squared = ratio * ratio;
  // atan on [0, 1]: a fifth-order minimax fit.
  double angle = ((-0.0464964749 * squared + 0.15931422) * squared - 0.327622764) * squared * ratio + ratio;
  if (absolute_y > absolute_x) {
    angle = 0.5 * kPi - angle;
  }
  if (x < 0.0) {
    angle = kPi - angle;
  }
  return y < 0.0 ? -angle : angle;
}

std::size_t binOf(double azimuth)
{
  // Azimuths come from fastAtan2, less a bin's half width at most: within one turn of [0, 2 pi).
  double wrapped = azimuth;
  if (wrapped < 0.0) {
    wrapped += 2.0 * kPi;
  }
  if (wrapped >= 2.0 * kPi) {
    wrapped -= 2.0 * kPi;
  }
  return std::min(kBins - 1, static_cast<std::size_t>(std::max(0.0, wrapped) / kBinRad));
}

}  // namespace

FreeSpaceView::FreeSpaceView(common::Span<const WorldPoint> points, const geometry::Point& origin,
                             const FreeSpaceSettings& settings)
    : origin_(origin), margin_m_(settings.margin_m), bins_(kBins)
{
  for (const WorldPoint& point : points) {
    if (!point.position_world.allFinite() || !point.sensor_world.allFinite() ||
        !std::isfinite(point.height_above_ground_m) || !(point.range_m >= settings.min_range_m)) {
      continue;
    }
    const double ground_z = point.position_world.z() - point.height_above_ground_m;
    const double sensor_height = point.sensor_world.z() - ground_z;
    const double end_height = point.height_above_ground_m;
    if (sensor_height < settings.ground_clearance_m || sensor_height > settings.vehicle_height_m) {
      continue;  // a sensor outside the band sees no free space in it
    }
    // The part of the ray inside the height band: a ray into the ground leaves it at the clearance, one
    // that climbs leaves it at the vehicle's height; a return inside the band ends it there.
    double inside = 1.0;
    if (end_height < settings.ground_clearance_m) {
      inside = (sensor_height - settings.ground_clearance_m) / (sensor_height - end_height);
    } else if (end_height > settings.vehicle_height_m) {
      inside = (settings.vehicle_height_m - sensor_height) / (end_height - sensor_height);
    }
    const geometry::Point start = point.sensor_world.head<2>();
    const geometry::Point along = point.position_world.head<2>() - start;
    const geometry::Point free_end = start + inside * along - origin;
    const auto free_range = static_cast<float>(free_end.norm());
    if (!(free_range > 0.0F)) {
      continue;
    }
    ++rays_;
    sensor_height_m_ = std::max(sensor_height_m_, sensor_height);
    Bin& bin = bins_[binOf(fastAtan2(free_end.y(), free_end.x()))];
    if (end_height <= sensor_height) {
      bin.level_reach = std::max(bin.level_reach, free_range);
    } else if (free_range > bin.climbing_reach && along.squaredNorm() > 0.0) {
      bin.climbing_reach = free_range;
      bin.climb = static_cast<float>((end_height - sensor_height) / along.norm());
    }
  }
}

bool FreeSpaceView::binSeesThrough(const Bin& bin, double range, double needed, double top_m) const
{
  // A ray over a low obstacle does not show it gone: it must cross the cell no higher than what was seen
  // in it (a ray that does not climb is nowhere higher than the sensor).
  return (bin.level_reach >= needed && top_m >= sensor_height_m_) ||
         (bin.climbing_reach >= needed && top_m >= sensor_height_m_ + bin.climb * range);
}

std::pair<std::size_t, std::size_t> FreeSpaceView::binsAcross(const geometry::Point& centre,
                                                              double half_diagonal, double& range) const
{
  const geometry::Point offset = centre - origin_;
  range = offset.norm();
  if (rays_ == 0 || !(range > half_diagonal)) {
    return {0, 0};
  }
  const double azimuth = fastAtan2(offset.y(), offset.x());
  const double half_width = std::asin(half_diagonal / range);
  const std::size_t first = binOf(azimuth - half_width);
  const std::size_t last = binOf(azimuth + half_width);
  return {first, (last + kBins - first) % kBins + 1};
}

bool FreeSpaceView::seesThrough(const geometry::Point& centre, double cell_size_m, double top_m) const
{
  const double half_diagonal = cell_size_m * std::sqrt(0.5);
  double range = 0.0;
  const auto [first, count] = binsAcross(centre, half_diagonal, range);
  if (count == 0) {
    return false;
  }
  const double needed = range + half_diagonal + margin_m_;
  for (std::size_t step = 0; step < count; ++step) {
    if (!binSeesThrough(bins_[(first + step) % kBins], range, needed, top_m)) {
      return false;
    }
  }
  return true;
}

bool FreeSpaceView::reaches(const geometry::Point& centre, double cell_size_m) const
{
  const double half_diagonal = cell_size_m * std::sqrt(0.5);
  double range = 0.0;
  const auto [first, count] = binsAcross(centre, half_diagonal, range);
  if (count == 0) {
    return false;
  }
  const double needed = range - half_diagonal;
  for (std::size_t step = 0; step < count; ++step) {
    const Bin& bin = bins_[(first + step) % kBins];
    if (!(std::max(bin.level_reach, bin.climbing_reach) >= needed)) {
      return false;
    }
  }
  return true;
}

}  // namespace ifar::perception
