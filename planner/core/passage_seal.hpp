#pragma once
// Sealing a passage the vehicle could not get through (BLOCKED_PASSAGE from the executive). The planner's
// obstacles are inflated by a disc the vehicle's width across, so a gap narrower than the vehicle's
// rectangle plus its clearance can still look open; following stalls in it. The seal is a row of
// background cells across the narrowest free point between the vehicle and the waypoint it could not
// reach: inflated like every wall, they close the channel, and the graph routes around from the next frame.

#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/segment.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"

namespace ifar::planner {

struct PassageSeal {
  geometry::Point centre = geometry::Point::Zero();  // the narrowest free point, world frame
  double half_width_m = 0.0;                         // its distance to the nearest (inflated) obstacle
  std::vector<geometry::Point> cells;                // background cells to remember, across the segment
                                                     // from its right to its left
  geometry::Segment
      across;  // the closed line: through the cells, reaching the inflation beyond the outer ones
};

/// The seal of the segment `from` -> `to` in `obstacles` (inflated by `inflation_m`): the free point of the
/// segment at least `inflation_m` + `cell_size_m` from `from` (so the vehicle is not sealed in) with the
/// least distance to an obstacle, and cells `cell_size_m` apart across the segment through it, out to both
/// sides while a cell is free or at most `inflation_m` - `cell_size_m` inside the inflated obstacles (short
/// of the obstacle itself). Empty when the segment has no such free point (too short, or blocked all along).
std::optional<PassageSeal> sealPassage(const graph::ObstacleSet& obstacles, const geometry::Point& from,
                                       const geometry::Point& to, double inflation_m, double cell_size_m);

/// Removes the graph's visibility edges that cross `seal.across`: an edge from a vertex in view to one
/// out of view survives the merge (unknown space is attemptable), and one through the passage would keep
/// the route there. Returns how many.
std::size_t removeEdgesThroughSeal(const PassageSeal& seal, graph::DvGraph& graph);

}  // namespace ifar::planner
