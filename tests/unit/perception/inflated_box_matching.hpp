#pragma once
// Test helpers: how far a traced polygon is from the outline of a box grown by a radius.

#include <algorithm>
#include <cmath>

#include "common/geometry/polygon.hpp"
#include "planner/perception/local_layer.hpp"

namespace ifar::perception::testing {

/// Distance from `point` to the closed box (0 inside).
inline double distanceToBox(const geometry::Polygon& box, const geometry::Point& point)
{
  return geometry::containsPoint(box, point) ? 0.0 : geometry::distanceToBoundary(box, point);
}

/// The largest gap, both ways, between `polygon` and the outline of `box` grown by `radius`:
/// every polygon vertex against the grown outline, and sampled outline points against the polygon.
inline double mismatchToInflatedBox(const geometry::Polygon& polygon, const geometry::Polygon& box,
                                    double radius)
{
  double worst = 0.0;
  for (const geometry::Point& vertex : polygon) {
    worst = std::max(worst, std::abs(distanceToBox(box, vertex) - radius));
  }
  // Outline of the grown box: each box vertex offset along directions around it covers edges and arcs.
  constexpr int kDirections = 72;
  for (const geometry::Point& corner : box) {
    for (int step = 0; step < kDirections; ++step) {
      const double angle = 2.0 * 3.14159265358979323846 * step / kDirections;
      const geometry::Point candidate = corner + radius * geometry::Point(std::cos(angle), std::sin(angle));
      if (distanceToBox(box, candidate) < radius - 1e-9) {
        continue;  // inside the grown box, not on its outline
      }
      worst = std::max(worst, geometry::distanceToBoundary(polygon, candidate));
    }
  }
  for (std::size_t index = 0; index < box.size(); ++index) {
    const geometry::Segment edge = geometry::polygonEdge(box, index);
    const geometry::Vector along = (edge.end - edge.start) / edge.length();
    const geometry::Vector outward(along.y(), -along.x());  // box given counter-clockwise
    for (double fraction = 0.0; fraction <= 1.0; fraction += 0.05) {
      const geometry::Point sample = edge.start + fraction * (edge.end - edge.start) + radius * outward;
      worst = std::max(worst, geometry::distanceToBoundary(polygon, sample));
    }
  }
  return worst;
}

inline std::vector<LayerPolygon> polygonsOf(const LocalLayer& layer, ObstacleClass obstacle_class,
                                            BoundaryKind boundary)
{
  std::vector<LayerPolygon> selected;
  for (const LayerPolygon& polygon : layer.polygons) {
    if (polygon.obstacle_class == obstacle_class && polygon.boundary == boundary) {
      selected.push_back(polygon);
    }
  }
  return selected;
}

}  // namespace ifar::perception::testing
