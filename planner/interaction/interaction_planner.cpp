#include "planner/interaction/interaction_planner.hpp"

#include <optional>
#include <utility>

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
  const bool extends = settings.search.extended_search_radius_m > settings.search.search_radius_m;
  std::optional<PushPlanner> extended;  // built for the first pair the near search proves impossible
  for (const OrderedPair& pair : interactions.connectivity.pairs) {
    const geometry::Point& from = interactions.connectivity.waypoints[pair.from].position;
    const geometry::Point& to = interactions.connectivity.waypoints[pair.to].position;
    PushPlan plan = planner.plan(from, to);
    if (extends && plan.status == PlanStatus::Exhausted) {
      if (!extended) {
        extended.emplace(problem, settings.pusher, extendedSearch(settings.search), settings.connectivity);
      }
      PushPlan wider = extended->plan(from, to);
      wider.expansions += plan.expansions;
      wider.planning_time_s += plan.planning_time_s;
      plan = std::move(wider);
    }
    interactions.plans.push_back(PairPlan{pair, std::move(plan)});
  }
  return interactions;
}

}  // namespace ifar::interaction
