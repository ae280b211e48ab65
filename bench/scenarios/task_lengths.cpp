#include "bench/scenarios/task_lengths.hpp"

namespace ifar::scenarios {

ExactOptimum exactOptimum(const ScenarioMaps& maps, const geometry::Point& start, const geometry::Point& goal,
                          graph::SearchScratch& scratch, bool allow_snapping)
{
  const graph::SearchResult result =
      graph::findPath(maps.exact_search, maps.exact.obstacles, start, goal, scratch);
  const bool snapped = result.start_snapped || result.goal_snapped;
  if (result.status != graph::SearchStatus::Found || (snapped && !allow_snapping) || result.path.size() < 2) {
    return {};
  }
  const geometry::Point first_leg = result.path[1].position - result.path[0].position;
  return {result.length, std::atan2(first_leg.y(), first_leg.x())};
}

double lengthOn(const PlanningGraph& map, const geometry::Point& start, const geometry::Point& goal,
                graph::SearchScratch& scratch, double goal_tolerance_m)
{
  const graph::SearchResult result = graph::findPath(map.search, map.map.obstacles, start, goal, scratch);
  if (result.status != graph::SearchStatus::Found ||
      (result.goal_snapped && (result.goal - goal).norm() > goal_tolerance_m)) {
    return NAN;
  }
  return result.length;
}

}  // namespace ifar::scenarios
