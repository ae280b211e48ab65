#include "planner/perception/height_filter.hpp"

#include <cmath>

namespace ifar::perception {

HeightFilterResult filterObstaclePoints(common::Span<const WorldPoint> points,
                                        const PerceptionSettings& settings)
{
  HeightFilterResult result;
  result.obstacle_points.reserve(points.size());
  for (const WorldPoint& point : points) {
    if (!point.position_world.allFinite() || !std::isfinite(point.height_above_ground_m) ||
        !std::isfinite(point.range_m)) {
      ++result.counts.non_finite;
      continue;
    }
    if (point.range_m < settings.min_range_m) {
      ++result.counts.too_close;
      continue;
    }
    if (point.height_above_ground_m < settings.ground_clearance_m ||
        point.height_above_ground_m > settings.vehicle_height_m) {
      ++result.counts.outside_height_band;
      continue;
    }
    result.obstacle_points.push_back(point);
  }
  result.counts.kept = result.obstacle_points.size();
  return result;
}

}  // namespace ifar::perception
