#include "bench/scenarios/search_suite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <utility>

#include "bench/baselines/cpu_clock.hpp"
#include "bench/baselines/grid_astar.hpp"
#include "bench/scenarios/forked_items.hpp"

namespace ifar::scenarios {
namespace {

constexpr auto kBlocked = grid_map::UnknownPolicy::AsBlocked;

std::string statusName(baselines::BaselineStatus status)
{
  switch (status) {
    case baselines::BaselineStatus::Solved:
      return "solved";
    case baselines::BaselineStatus::NoPath:
      return "no_path";
    case baselines::BaselineStatus::Timeout:
      return "timeout";
    case baselines::BaselineStatus::InvalidStart:
      return "invalid_start";
    case baselines::BaselineStatus::InvalidGoal:
      return "invalid_goal";
    case baselines::BaselineStatus::Error:
      return "error";
  }
  return "error";
}

std::vector<geometry::Point> positions(const graph::SearchResult& result)
{
  std::vector<geometry::Point> points;
  points.reserve(result.path.size());
  for (const graph::PathPoint& point : result.path) {
    points.push_back(point.position);
  }
  return points;
}

/// Runs `query` `repeats` times (at least once): its last result and the median planner-thread CPU ms.
/// The previous result is released after the clock stops, so freeing it is not timed.
template <typename Query>
auto timedMedian(int repeats, const Query& query)
{
  std::optional<decltype(query())> result;
  std::vector<double> times;
  for (int run = 0; run < std::max(1, repeats); ++run) {
    const double began = baselines::threadCpuMilliseconds();
    auto latest = query();
    times.push_back(baselines::threadCpuMilliseconds() - began);
    result = std::move(latest);
  }
  const auto middle = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
  std::nth_element(times.begin(), middle, times.end());
  return std::make_pair(std::move(*result), *middle);
}

ResultRow graphRow(const graph::SearchResult& result, double milliseconds, const PlanningGraph& planning)
{
  ResultRow row;
  const bool found = result.status == graph::SearchStatus::Found;
  row.success = found;
  row.length = found ? result.length : NAN;
  row.ms = milliseconds;
  row.status = found ? "solved" : "no_path";
  if (!found) {
    row.reason = std::string("search: ") + graph::toString(result.status);
  }
  row.graph_vertices = static_cast<double>(planning.map.graph.vertexCount());
  return row;
}

/// One planner's query: its result, length, status and reason, planner-thread CPU ms and map size.
ResultRow plannedRow(const std::string& planner, const Task& task, const graph::SearchResult& far_reference,
                     const ScenarioMaps& maps, const SearchSuiteSettings& settings,
                     baselines::GridAStar& grid_search, graph::SearchScratch& scratch)
{
  ResultRow row;
  if (planner == "grid_astar") {
    const auto [result, ms] =
        timedMedian(settings.timing_repeats, [&] { return grid_search.findPath(task.start, task.goal); });
    row.ms = ms;
    row.success = result.solved();
    row.length = result.solved() ? result.length : NAN;
    row.status = statusName(result.status);
    row.reason = result.solved() ? "" : (result.reason.empty() ? row.status : result.reason);
    row.graph_vertices = static_cast<double>(maps.planning_grid.width()) * maps.planning_grid.height();
  } else if (planner == "rrt_star" || planner == "bit_star") {
    row.graph_vertices = static_cast<double>(maps.far.map.obstacles.edgeCount());
    if (far_reference.status != graph::SearchStatus::Found) {
      // Sampling cannot find what the exact search proved absent; running to the cap says nothing.
      row.status = "no_path";
      row.ms = NAN;
      row.reason =
          "not run: no collision-free path on this map (movable objects as obstacles), "
          "proved by the exact visibility search";
    } else {
      const auto algorithm = planner == "rrt_star" ? baselines::SamplingAlgorithm::RrtStar
                                                   : baselines::SamplingAlgorithm::BitStar;
      const baselines::BaselineResult result = baselines::planSampling(
          algorithm, maps.far.map.obstacles, task.start, task.goal, far_reference.length, settings.sampling);
      row.ms = result.milliseconds;
      row.success = result.solved();
      row.length = std::isfinite(result.length) && result.length > 0.0 ? result.length : NAN;
      row.status = statusName(result.status);
      row.reason = result.solved() ? "" : (result.reason.empty() ? row.status : result.reason);
    }
  } else if (planner == "far" || planner == "ours") {
    const PlanningGraph& planning = planner == "far" ? maps.far : maps.ours;
    const auto [result, ms] = timedMedian(settings.timing_repeats, [&] {
      return graph::findPath(planning.search, planning.map.obstacles, task.start, task.goal, scratch);
    });
    row = graphRow(result, ms, planning);
  } else {
    row.status = "error";
    row.reason = "unknown planner '" + planner + "'";
  }
  return row;
}

}  // namespace

const std::vector<std::string>& searchPlanners()
{
  static const std::vector<std::string> planners{"grid_astar", "rrt_star", "bit_star", "far", "ours"};
  return planners;
}

std::vector<ResultRow> runSearchSuite(ScenarioKind kind, const std::string& world_name,
                                      const ScenarioMaps& maps, const std::vector<Task>& tasks,
                                      const SearchSuiteSettings& settings, PlannedPaths* paths)
{
  baselines::GridAStar grid_search(maps.planning_grid, kBlocked);
  graph::SearchScratch scratch;
  // One untimed run of each deterministic search first, so the first timed query does not pay for cold
  // caches and first-touch page faults.
  if (!tasks.empty()) {
    grid_search.findPath(tasks.front().start, tasks.front().goal);
    graph::findPath(maps.far.search, maps.far.map.obstacles, tasks.front().start, tasks.front().goal,
                    scratch);
    graph::findPath(maps.ours.search, maps.ours.map.obstacles, tasks.front().start, tasks.front().goal,
                    scratch);
  }
  // FAR mode's exact length on the planners' map: the sampling planners' target (within the factor of
  // the best path that map allows) and proof that no path exists when it finds none.
  std::vector<graph::SearchResult> far_references;
  for (const Task& task : tasks) {
    far_references.push_back(
        graph::findPath(maps.far.search, maps.far.map.obstacles, task.start, task.goal, scratch));
    if (paths != nullptr) {
      paths->far.push_back(positions(far_references.back()));
      paths->ours.push_back(positions(
          graph::findPath(maps.ours.search, maps.ours.map.obstacles, task.start, task.goal, scratch)));
    }
  }
  const std::size_t planner_count = settings.planners.size();
  std::vector<ResultRow> rows(tasks.size() * planner_count);
  // The queries run in order in one child process (a new one after a crash or a hang), so a baseline
  // that dies costs its own row only, and each query finds the caches and heap its predecessors left.
  ForkedItems queries;
  queries.count = rows.size();
  queries.items_per_child = rows.size();
  queries.answer = [&](std::size_t index) {
    const std::size_t task_index = index / planner_count;
    ResultRow row;
    try {
      row = plannedRow(settings.planners[index % planner_count], tasks[task_index],
                       far_references[task_index], maps, settings, grid_search, scratch);
    } catch (const std::exception& error) {
      row.length = NAN;
      row.ms = NAN;
      row.status = "error";
      row.reason = std::string("planner threw: ") + error.what();
    }
    return toAnswer(row);
  };
  queries.deadline = [&](std::size_t) { return settings.query_deadline; };
  queries.finished = [&](std::size_t index, const ForkedOutcome& outcome) {
    const std::optional<ResultRow> answered = outcome.answered ? rowFromAnswer(outcome.answer) : std::nullopt;
    ResultRow row;
    if (answered) {
      row = *answered;
    } else {
      row.length = NAN;
      row.ms = NAN;
      row.status = outcome.answered ? "error" : outcome.status;
      row.reason = outcome.answered ? "its child process's answer could not be read" : outcome.reason;
    }
    const Task& task = tasks[index / planner_count];
    row.table = "search";
    row.planner = settings.planners[index % planner_count];
    row.kind = kindName(kind);
    row.world = world_name;
    row.task = task.id;
    row.optimal = task.optimal;
    row.achievable = task.achievable;
    row.without_pushing = task.without_pushing;
    if (!task.reachable_with_pushing) {
      row.success = false;
      row.status = "unreachable";
      row.reason = "unreachable even with pushing: objects too heavy for the vehicle close every route";
    }
    rows[index] = row;
  };
  runForked(queries);
  return rows;
}

}  // namespace ifar::scenarios
