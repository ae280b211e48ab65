#pragma once
// Where one push search must get: the passage between two topological waypoints, and the ways on beyond
// the object that the push must leave open.

#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/geometry/segment.hpp"

namespace ifar::interaction {

struct PushGoalRegion {
  geometry::Segment segment;  ///< from the start waypoint to the goal waypoint
  geometry::Polygon window;   ///< the passage rectangle widened by the inflation, counter-clockwise
  /// Per surroundings raster cell: the outlet (1, 2, ...) it belongs to, 0 for none. An outlet is one
  /// stretch of the raster's edge where the start's or the goal's side of the unmoved object leaves the
  /// raster (none when the object separates nothing there, or without an onward check).
  std::vector<int> outlets;
  int outlet_count = 0;  ///< every outlet must stay reachable from the start waypoint ...
  /// ... within this many raster steps (index: outlet): its steps from the start waypoint with the object
  /// gone plus a detour round the object; no bound where the object gone does not reach it either.
  std::vector<int> outlet_step_limits;
};

}  // namespace ifar::interaction
