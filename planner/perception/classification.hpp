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

/// How a point's tag is read: its own reflectivity, or its neighbours' as well.
struct TagReading {
  /// Points at or above this reflectivity carry a tag (a retro-reflective marker on a movable object).
  float threshold = 101.0F;
  /// 0: each point by its own reflectivity. Otherwise a point whose tag disagrees with more than
  /// `overrule_ratio` times as many returns of its neighbourhood (the points in its cell of this side and
  /// the eight around it, itself included) as agree takes theirs: a lidar misses a tag's return now and
  /// then (dirt, an oblique hit) and reads a bright wall as a tag, and one such return kept as a wall on a
  /// movable object makes it a wall for good.
  double neighbourhood_m = 0.0;
  double overrule_ratio = 2.0;
};

/// Movable when the point carries a tag (`reading`).
ClassifiedPoints classifyByReflectivity(common::Span<const WorldPoint> points, const TagReading& reading);

/// Movable when inside (or on the boundary of) any detector polygon (world frame); reflectivity is
/// ignored. An empty polygon list makes every point background.
ClassifiedPoints classifyByDetector(common::Span<const WorldPoint> points,
                                    common::Span<const geometry::Polygon> detector_polygons);

}  // namespace ifar::perception
