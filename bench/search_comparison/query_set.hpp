#pragma once
// The queries of a comparison run and their ground truth: the exact shortest length among the static
// obstacles without inflation (the DV-graph search on the cell-boundary polygons, exact by construction).

#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/grid_map/grid_map.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace ifar::bench {

struct Query {
  std::string task;  // "q0", "q1", ... or "scen12"
  geometry::Point start = geometry::Point::Zero();
  geometry::Point goal = geometry::Point::Zero();
  double optimal = 0.0;  // exact, zero inflation; NaN when start and goal are not connected
};

struct RandomQuerySettings {
  int count = 10;
  std::uint64_t seed = 1;
  double min_length = 0.0;  // keep only queries whose optimum is at least this long
  int max_attempts_per_query = 200;
};

/// The exact optimum between two points on `exact` (a zero-inflation prior map); NaN when not connected.
double exactOptimum(const graph::PriorMap& exact, const geometry::Point& start, const geometry::Point& goal);

/// Seeded random queries between centres of cells that are free in `planning_grid` (the map the
/// planners see) and connected in both `planning` (the DV-graph the planners' map gives) and `exact`.
/// Fewer than `count` come back when the map has too few such pairs.
std::vector<Query> randomQueries(const grid_map::GridMap& planning_grid, grid_map::UnknownPolicy policy,
                                 const graph::PriorMap& planning, const graph::PriorMap& exact,
                                 const RandomQuerySettings& settings);

}  // namespace ifar::bench
