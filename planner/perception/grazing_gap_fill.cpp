#include "planner/perception/grazing_gap_fill.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "common/geometry/angle.hpp"

namespace ifar::perception {
namespace {

constexpr double kTwoPi = 2.0 * geometry::kPi;
// Range noise allowed on top of the geometric spacing, metres.
constexpr double kRangeNoiseM = 0.05;

struct BinReturn {
  geometry::Point point = geometry::Point::Zero();
  double range_m = std::numeric_limits<double>::infinity();
  double azimuth_rad = 0.0;
  bool movable = false;
};

bool isEmpty(const BinReturn& bin)
{
  return !std::isfinite(bin.range_m);
}

void keepNearest(common::Span<const geometry::Point> points, bool movable, const geometry::Point& sensor,
                 double bin_rad, std::vector<BinReturn>& bins)
{
  for (const geometry::Point& point : points) {
    const geometry::Point offset = point - sensor;
    const double range = offset.norm();
    if (!std::isfinite(range) || range <= 0.0) {
      continue;
    }
    const double azimuth = std::atan2(offset.y(), offset.x()) + geometry::kPi;  // 0 .. 2 pi
    const std::size_t index = std::min(static_cast<std::size_t>(azimuth / bin_rad), bins.size() - 1);
    BinReturn& bin = bins[index];
    if (range < bin.range_m) {
      bin = {point, range, azimuth, movable};
    }
  }
}

// Whether the returns are of neighbouring rays (at most `most_apart` in azimuth) and a surface seen at no
// less than `min_incidence` could hold both: from the nearer one, a neighbour `angle` further round lies at
// most range * sin(angle) / sin(min_incidence - angle) away.
bool onOneSurface(const BinReturn& first, const BinReturn& second, double min_incidence, double most_apart)
{
  double angle = std::abs(second.azimuth_rad - first.azimuth_rad);
  if (angle > geometry::kPi) {
    angle = kTwoPi - angle;
  }
  if (angle > most_apart || angle >= min_incidence) {
    return false;
  }
  const double nearer = std::min(first.range_m, second.range_m);
  const double most = nearer * std::sin(angle) / std::sin(min_incidence - angle) + kRangeNoiseM;
  return (second.point - first.point).norm() <= most;
}

void addJoin(const geometry::Point& from, const geometry::Point& to, double spacing,
             std::vector<geometry::Point>& fill)
{
  const double length = (to - from).norm();
  const auto steps = static_cast<int>(std::ceil(length / spacing));
  for (int step = 1; step < steps; ++step) {
    fill.push_back(from + (to - from) * (static_cast<double>(step) / steps));
  }
}

}  // namespace

std::vector<geometry::Point> fillGrazingGaps(common::Span<const geometry::Point> background,
                                             common::Span<const geometry::Point> movable,
                                             const geometry::Point& sensor,
                                             const GrazingGapSettings& settings)
{
  std::vector<geometry::Point> fill;
  if (!(settings.azimuth_step_rad > 0.0) || !(settings.spacing_m > 0.0) || !sensor.allFinite()) {
    return fill;
  }
  // Bins a quarter step wide, the nearest return of each kept. A firing's lasers spread over two thirds of
  // a step (a VLP-16 fires them 2.3 us apart), so returns of the same or the next firing lie under 1.25
  // steps apart unless they are over 1.33 steps apart: between those, a firing returned nothing.
  const double bin_rad = 0.25 * settings.azimuth_step_rad;
  const auto count = static_cast<std::size_t>(std::ceil(kTwoPi / bin_rad));
  std::vector<BinReturn> bins(count);
  keepNearest(background, false, sensor, bin_rad, bins);
  keepNearest(movable, true, sensor, bin_rad, bins);
  std::vector<std::size_t> occupied;
  for (std::size_t index = 0; index < count; ++index) {
    if (!isEmpty(bins[index])) {
      occupied.push_back(index);
    }
  }
  if (occupied.size() < 2) {
    return fill;
  }
  const double most_apart = 1.25 * settings.azimuth_step_rad;
  for (std::size_t position = 0; position < occupied.size(); ++position) {
    const BinReturn& first = bins[occupied[position]];
    const BinReturn& second = bins[occupied[(position + 1) % occupied.size()]];  // round past 2 pi
    if (first.movable || second.movable) {
      continue;
    }
    if (onOneSurface(first, second, settings.min_incidence_rad, most_apart)) {
      addJoin(first.point, second.point, settings.spacing_m, fill);
    }
  }
  return fill;
}

}  // namespace ifar::perception
