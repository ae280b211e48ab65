#pragma once
// Keeps the returns that are obstacles for the vehicle: finite, not too close to the sensor, and
// between the ground clearance and the vehicle's height above the ground.

#include <cstddef>
#include <vector>

#include "common/span.hpp"
#include "planner/perception/perception_settings.hpp"
#include "planner/perception/world_point.hpp"

namespace ifar::perception {

struct HeightFilterCounts {
  std::size_t non_finite = 0;           // NaN or infinite position: malformed input, counted and skipped
  std::size_t too_close = 0;            // within min_range_m of the sensor
  std::size_t outside_height_band = 0;  // ground, overhangs the vehicle passes under
  std::size_t kept = 0;
};

struct HeightFilterResult {
  std::vector<WorldPoint> obstacle_points;
  HeightFilterCounts counts;
};

HeightFilterResult filterObstaclePoints(common::Span<const WorldPoint> points,
                                        const PerceptionSettings& settings);

}  // namespace ifar::perception
