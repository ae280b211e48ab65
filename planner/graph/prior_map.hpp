#pragma once
// A prior map: the DV-graph built once from an occupancy grid (MovingAI .map, map_server PGM+YAML).

#include "common/grid_map/grid_map.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/visibility_builder.hpp"

namespace ifar::graph {

struct PriorMap {
  ObstacleSet obstacles;
  DvGraph graph;
  BuildStats stats;
};

/// Inflates the grid by `inflate_radius` (world units; 0 keeps the exact GPPC geometry), traces the
/// cell-boundary loops (the map's rim included, everything outside is blocked) and builds the reduced
/// visibility graph on every core of the machine (a one-off build before the run). Unknown cells count
/// as `unknown_policy` says.
PriorMap buildPriorMap(const grid_map::GridMap& map, double inflate_radius,
                       grid_map::UnknownPolicy unknown_policy = grid_map::UnknownPolicy::AsFree,
                       const ProgressCallback& progress = {});

}  // namespace ifar::graph
