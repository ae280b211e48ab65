#pragma once
// A wall perceived as a single raster cell becomes, inflated, a rectangle only about twice the inflation
// wide (0.15 m cells and 0.35 m inflation: 0.75 m). No point of it lies deeper than the depth a pushed
// object may reach into an obstacle, so the depth test alone lets the object through it. For these the
// test is whether a footprint point crosses the rectangle's middle line: the face as perceived.

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/interaction/convex_polygon.hpp"

namespace ifar::interaction {

struct ThinWall {
  Bounds bounds;
  geometry::Point centre;
  geometry::Vector across;  ///< unit, along the rectangle's short side
  geometry::Vector along;   ///< unit, along its long side
  double reach = 0.0;       ///< how far from the centre along the middle line the face reaches
  /// exempt[side][sample]: the collision checker's sample of that side is not held to this face.
  std::array<std::vector<bool>, 2> exempt;

  /// Whether a point moving from `start` to `end` crosses the face (touching it does not count). Inline:
  /// every collision check asks it for each boundary point.
  bool crossedBy(const geometry::Point& start, const geometry::Point& end) const
  {
    const double start_offset = (start - centre).dot(across);
    const double end_offset = (end - centre).dot(across);
    if (start_offset * end_offset >= 0.0) {
      return false;  // stays on one side of the face (or touches it)
    }
    const geometry::Point crossing = start + (end - start) * (start_offset / (start_offset - end_offset));
    return std::abs((crossing - centre).dot(along)) <= reach;
  }
};

/// `obstacle` as a thin wall: a rectangle whose half width lies between `inflation` and `allowed_depth`.
std::optional<ThinWall> thinWall(const geometry::Polygon& obstacle, double inflation, double allowed_depth);

}  // namespace ifar::interaction
