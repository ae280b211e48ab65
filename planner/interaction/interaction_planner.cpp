#include "planner/interaction/interaction_planner.hpp"

#include "planner/interaction/push_search.hpp"

namespace ifar::interaction {

ObjectInteractions planObjectInteractions(const LocalScene& scene, std::size_t movable_index,
                                          const ObjectPhysics& physics, const InteractionSettings& settings)
{
  ObjectInteractions interactions;
  interactions.connectivity = analyzeConnectivity(scene, movable_index, settings.connectivity);
  if (!interactions.connectivity.splits) {
    return interactions;
  }
  PushProblemObject problem;
  problem.object = scene.movable[movable_index];
  std::size_t skipped = 0;
  problem.obstacles = obstaclesFor(scene, movable_index, settings.connectivity, skipped);
  problem.physics = physics;
  const PushPlanner planner(problem, settings.pusher, settings.search, settings.connectivity);
  for (const OrderedPair& pair : interactions.connectivity.pairs) {
    interactions.plans.push_back(
        PairPlan{pair, planner.plan(interactions.connectivity.waypoints[pair.from].position,
                                    interactions.connectivity.waypoints[pair.to].position)});
  }
  return interactions;
}

}  // namespace ifar::interaction
