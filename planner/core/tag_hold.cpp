#include "planner/core/tag_hold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "common/geometry/angle.hpp"
#include "common/geometry/polygon.hpp"
#include "drivers/velodyne/packet_format.hpp"

namespace ifar::planner {
namespace {

std::pair<std::int64_t, std::int64_t> cellOf(const geometry::Point& point, double cell_m)
{
  return {static_cast<std::int64_t>(std::floor(point.x() / cell_m)),
          static_cast<std::int64_t>(std::floor(point.y() / cell_m))};
}

}  // namespace

TagHoldSettings TagHoldSettings::fromVehicle(const common::VehicleSettings& vehicle, double margin_m)
{
  TagHoldSettings settings;
  settings.margin_m = margin_m;
  const double lowest_deg =
      *std::min_element(velodyne::kLaserElevationDegrees.begin(), velodyne::kLaserElevationDegrees.end());
  const double depression = std::tan(geometry::radiansFromDegrees(-lowest_deg));
  const double drop_m = vehicle.lidar_height_m - vehicle.lidar.ground_clearance_m;
  settings.face_range_m = depression > 0.0 && drop_m > 0.0 ? drop_m / depression : 0.0;
  return settings;
}

TagHold::Returns TagHold::heldNear(const geometry::Point& sensor) const
{
  Returns near;
  if (!enabled()) {
    return near;
  }
  for (const auto& [object_id, held] : held_) {
    const double nearer_squared = held.range_m * held.range_m;
    const bool nearer = std::any_of(
        held.points.begin(), held.points.end(),
        [&](const geometry::Point& point) { return (point - sensor).squaredNorm() < nearer_squared; });
    if (nearer) {
      near.movable.insert(near.movable.end(), held.points.begin(), held.points.end());
      near.background.insert(near.background.end(), held.background.begin(), held.background.end());
    }
  }
  return near;
}

void TagHold::observe(const std::vector<TrackedObject>& seen, common::Span<const geometry::Point> movable,
                      common::Span<const float> movable_heights_m,
                      common::Span<const geometry::Point> background, const geometry::Point& sensor)
{
  if (!enabled()) {
    return;
  }
  const double cell_m = 0.5 * settings_.margin_m;
  const bool heights = movable_heights_m.size() == movable.size();
  for (const TrackedObject& object : seen) {
    if (object.outline.size() < 3) {
      continue;
    }
    const Eigen::AlignedBox2d box = geometry::boundingBox(object.outline);
    const auto found = held_.find(object.id);
    const double needed_m = found != held_.end() ? found->second.range_m : 0.0;
    Held held;
    held.range_m = settings_.face_range_m;
    std::vector<geometry::Point> own;
    std::set<std::pair<std::int64_t, std::int64_t>> cells;
    for (std::size_t index = 0; index < movable.size(); ++index) {
      const geometry::Point& point = movable[index];
      if (!point.allFinite() || !box.contains(point) || !geometry::containsPoint(object.outline, point)) {
        continue;
      }
      own.push_back(point);
      held.range_m = std::min(held.range_m, (point - sensor).norm());
      if (heights) {
        held.top_m = std::max(held.top_m, static_cast<double>(movable_heights_m[index]));
      }
      if (cells.insert(cellOf(point, cell_m)).second) {
        held.points.push_back(point);
      }
    }
    if (found != held_.end() && held.range_m < needed_m && !own.empty()) {
      // A nearer view: the object keeps what was held, unless most of its tagged returns now lie away from
      // where it was held (it was pushed: what stands there now is not the object).
      std::set<std::pair<std::int64_t, std::int64_t>> held_cells;
      for (const geometry::Point& point : found->second.points) {
        held_cells.insert(cellOf(point, cell_m));
      }
      std::size_t away = 0;
      for (const geometry::Point& point : own) {
        const auto [column, row] = cellOf(point, cell_m);
        bool near = false;
        for (std::int64_t dc = -2; dc <= 2 && !near; ++dc) {
          for (std::int64_t dr = -2; dr <= 2 && !near; ++dr) {
            near = held_cells.count({column + dc, row + dr}) > 0;
          }
        }
        away += near ? 0 : 1;
      }
      if (2 * away > own.size()) {
        held_.erase(found);
      }
      continue;
    }
    // A nearer scan shows less of the object's face than the one held.
    if (held.range_m >= needed_m && !held.points.empty()) {
      cells.clear();
      for (const geometry::Point& point : background) {
        if (!point.allFinite() || !box.contains(point) || !geometry::containsPoint(object.outline, point)) {
          continue;
        }
        if (cells.insert(cellOf(point, cell_m)).second) {
          held.background.push_back(point);
        }
      }
      if (!heights) {
        held.top_m = std::numeric_limits<double>::infinity();
      }
      held_[object.id] = std::move(held);
    }
  }
}

std::size_t TagHold::releaseSeenThrough(const perception::FreeSpaceView& view, double cell_size_m)
{
  std::size_t released = 0;
  if (view.empty()) {
    return released;
  }
  for (auto found = held_.begin(); found != held_.end();) {
    std::vector<geometry::Point>& points = found->second.points;
    const double top_m = found->second.top_m;
    const auto gone = std::remove_if(points.begin(), points.end(), [&](const geometry::Point& point) {
      return view.seesThrough(point, cell_size_m, top_m);
    });
    released += static_cast<std::size_t>(points.end() - gone);
    points.erase(gone, points.end());
    found = points.empty() ? held_.erase(found) : std::next(found);
  }
  return released;
}

std::vector<geometry::Point> TagHold::heldOf(std::int64_t object_id) const
{
  const auto found = held_.find(object_id);
  return found != held_.end() ? found->second.points : std::vector<geometry::Point>{};
}

}  // namespace ifar::planner
