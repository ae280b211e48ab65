#include "planner/graph/prior_map.hpp"

#include <algorithm>
#include <thread>

#include "common/grid_map/boundaries.hpp"

namespace ifar::graph {

PriorMap buildPriorMap(const grid_map::GridMap& map, double inflate_radius,
                       grid_map::UnknownPolicy unknown_policy, const ProgressCallback& progress)
{
  const grid_map::GridMap inflated = map.inflated(inflate_radius, unknown_policy);
  std::vector<ObstacleLoop> loops;
  for (auto& polygon : grid_map::blockedBoundaries(inflated, unknown_policy)) {
    loops.push_back(ObstacleLoop{std::move(polygon), 0});
  }
  const Bounds bounds{map.cornerToWorld(0, 0), map.cornerToWorld(map.width(), map.height())};
  PriorMap prior{ObstacleSet(std::move(loops), bounds), DvGraph(), BuildStats()};
  prior.stats = addReducedVisibilityGraph(prior.obstacles, prior.graph, nullptr, progress,
                                          std::max(1U, std::thread::hardware_concurrency()));
  prior.graph.shrinkToFit();
  return prior;
}

}  // namespace ifar::graph
