#pragma once
// Seeded synthetic obstacle fields for the graph benchmarks: rectangles, one per sub-cell of a regular
// grid (so they never overlap), random size and placement inside their sub-cell.

#include <cstdint>
#include <vector>

#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"

namespace ifar::graph::bench {

struct RectangleField {
  double width_m = 0.0;
  double height_m = 0.0;
  int columns = 0;          // sub-cells across
  int rows = 0;             // sub-cells down
  double min_side_m = 0.0;  // rectangle sides are drawn from [min_side, max_side], clipped to the sub-cell
  double max_side_m = 0.0;
  std::uint32_t seed = 1;
};

/// Counter-clockwise rectangles of the field (object id 0).
std::vector<ObstacleLoop> rectangles(const RectangleField& field);

/// The whole field's reduced visibility graph, built in one go.
DvGraph fullGraph(const ObstacleSet& obstacles);

/// The graph a robot would accumulate driving over the field: local layers of `window_m` squares
/// (stepping by half a window) built and merged one after another.
DvGraph mergedGraph(const std::vector<ObstacleLoop>& loops, double width_m, double height_m, double window_m);

}  // namespace ifar::graph::bench
