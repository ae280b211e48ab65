#pragma once
// Splits obstacle points into movable (S_mov) and background (S_bg), either by the reflectivity of
// retro-reflective tags or by the outlines an external detector publishes.

#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/span.hpp"
#include "planner/perception/world_point.hpp"

namespace ifar::perception {

/// Obstacle points projected onto the ground plane (world x, y), by class.
struct ClassifiedPoints {
  std::vector<geometry::Point> background;
  std::vector<geometry::Point> movable;
  /// Height above the ground of each point, as classified (empty when the points were made otherwise).
  std::vector<float> background_heights_m;
  std::vector<float> movable_heights_m;
};

/// Movable when reflectivity >= threshold.
ClassifiedPoints classifyByReflectivity(common::Span<const WorldPoint> points, float threshold);

/// Movable when inside (or on the boundary of) any detector polygon (world frame); reflectivity is
/// ignored. An empty polygon list makes every point background.
ClassifiedPoints classifyByDetector(common::Span<const WorldPoint> points,
                                    common::Span<const geometry::Polygon> detector_polygons);

}  // namespace ifar::perception
