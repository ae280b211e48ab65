#pragma once
// Splitting a simple polygon into convex pieces Box2D accepts (at most 8 vertices each).

#include <vector>

#include "common/geometry/polygon.hpp"

namespace ifar::sim::physics {

/// Signed shoelace area (> 0 counter-clockwise); local so physics does not depend on more than headers.
double signedPolygonArea(const geometry::Polygon& polygon);

/// The polygon itself when it is convex with at most `max_vertices` vertices, otherwise its ear-clipping
/// triangles. Pieces are counter-clockwise; slivers below `min_area` square metres are dropped. An input
/// that is not simple may lose area but never produces an invalid piece.
std::vector<geometry::Polygon> convexPieces(const geometry::Polygon& polygon, std::size_t max_vertices = 8,
                                            double min_area = 1e-6);

}  // namespace ifar::sim::physics
