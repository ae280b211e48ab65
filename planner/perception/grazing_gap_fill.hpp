#pragma once
// Far along a wall, neighbouring lidar rays land metres apart: a ray meeting a wall at 4 degrees 30 m away
// lands 3 m from its neighbour 0.4 degrees on. The inflated raster then shows gaps in the wall that no ray
// went through, and the planner, taking unseen space as free, routes through them until the vehicle comes
// close enough to see the wall whole. Joining returns of neighbouring rays that can lie on one surface
// closes such gaps for the current scan; a gap that a ray went through stays open, because that ray
// returned from far behind the wall, or from nothing between the ground and the vehicle's height.

#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"

namespace ifar::perception {

struct GrazingGapSettings {
  /// The lidar's azimuth step between firings, radians. Two returns at most 1.25 steps apart in azimuth
  /// had no firing between them. 0 turns the filling off.
  double azimuth_step_rad = 0.0;
  /// Such returns are joined when a surface seen at this angle or steeper (to the ray) could hold both,
  /// radians. Flatter surfaces are not joined: the gap may be a passage the next ray missed.
  double min_incidence_rad = 0.0;
  /// Fill points lie this far apart along a join, metres (at most half a layer cell).
  double spacing_m = 0.075;
};

/// Points along the joins of neighbouring rays' nearest returns (world frame, around `sensor`; the nearest
/// return per quarter azimuth step stands for its ray), where both are background: a movable return joins
/// nothing, so a movable object is never welded to a wall. Empty when settings.azimuth_step_rad is not
/// positive.
std::vector<geometry::Point> fillGrazingGaps(common::Span<const geometry::Point> background,
                                             common::Span<const geometry::Point> movable,
                                             const geometry::Point& sensor,
                                             const GrazingGapSettings& settings);

}  // namespace ifar::perception
