#pragma once
// The lengths a task is scored against, on one world's maps (scenario_maps.hpp): the exact ground truth
// (zero inflation, movable objects removed) and the shortest path on one of the planners' graphs (the
// achievable way with only the objects too heavy to push, or the way that never pushes).

#include <cmath>
#include <limits>

#include "bench/scenarios/scenario_maps.hpp"
#include "common/geometry/point.hpp"
#include "planner/graph/search.hpp"

namespace ifar::scenarios {

struct ExactOptimum {
  double length = NAN;   // NaN when there is no path
  double heading = 0.0;  // along the first leg
};

/// The exact shortest path among the static obstacles with the movable objects removed. Without
/// `allow_snapping` a start or goal the search had to move off an obstacle counts as no path (randomly
/// drawn pairs are only kept when both ends are free); with it, the snapped path's length (a world's own
/// goals may stand on a wall's rasterised edge).
ExactOptimum exactOptimum(const ScenarioMaps& maps, const geometry::Point& start, const geometry::Point& goal,
                          graph::SearchScratch& scratch, bool allow_snapping = false);

/// Length of the shortest path on `map`; NaN when there is none, or when the search had to move the goal
/// off an obstacle by more than `goal_tolerance_m` (a goal under a movable object is reached only by
/// pushing it away).
double lengthOn(const PlanningGraph& map, const geometry::Point& start, const geometry::Point& goal,
                graph::SearchScratch& scratch,
                double goal_tolerance_m = std::numeric_limits<double>::infinity());

}  // namespace ifar::scenarios
