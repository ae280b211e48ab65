#pragma once
// Tables I and II (planned paths): every planner on every task of one world, on the same map, in one
// process. Grid A* on the inflated grid, RRT* and BIT* (OMPL, exact segment checks) on the inflated
// polygons until within `optimum_factor` of the optimum on that map or the CPU cap, FAR mode (the
// DV-graph search without interaction edges) and ours (with them). Times are planner-thread CPU time;
// a deterministic planner's (grid A*, FAR mode, ours) is the median of `timing_repeats` runs of the
// query, since one run of a sub-millisecond search measures mostly the cache misses left by the planner
// timed before it.
//
// A task that is unreachable even with pushing is a failure for every planner (status "unreachable").
// A baseline that fails, times out, throws, crashes or hangs is a recorded failure with its reason, never
// dropped: the queries run in a child process (forked_items.hpp).

#include <chrono>
#include <string>
#include <vector>

#include "bench/baselines/sampling_planners.hpp"
#include "bench/scenarios/result_row.hpp"
#include "bench/scenarios/scenario_kind.hpp"
#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/task_selection.hpp"

namespace ifar::scenarios {

/// grid_astar, rrt_star, bit_star, far, ours.
const std::vector<std::string>& searchPlanners();

struct SearchSuiteSettings {
  std::vector<std::string> planners = searchPlanners();
  baselines::SamplingSettings sampling;
  int timing_repeats = 5;  ///< runs of each deterministic query; the median is reported (at least 1)
  /// Wall time one query (all its timing repeats) may take in its child process before it is killed
  /// and recorded as a timeout.
  std::chrono::milliseconds query_deadline{std::chrono::seconds(60)};
};

/// The planned path of FAR mode and ours per task, for the trajectory plots.
struct PlannedPaths {
  std::vector<std::vector<geometry::Point>> far;
  std::vector<std::vector<geometry::Point>> ours;
};

std::vector<ResultRow> runSearchSuite(ScenarioKind kind, const std::string& world_name,
                                      const ScenarioMaps& maps, const std::vector<Task>& tasks,
                                      const SearchSuiteSettings& settings, PlannedPaths* paths = nullptr);

}  // namespace ifar::scenarios
