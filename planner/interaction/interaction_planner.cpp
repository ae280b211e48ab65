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
  // The wider searches are built for the first pair the searches before them prove impossible.
  const bool extends = settings.search.extended_search_radius_m > settings.search.search_radius_m;
  const bool corridor = settings.search.corridor_push_length_m > 0.0;
  std::optional<PushPlanner> extended;
  std::optional<PushPlanner> along_corridor;
  const auto retry = [&](std::optional<PushPlanner>& wider, const SearchSettings& search,
                         const geometry::Point& from, const geometry::Point& to, PushPlan& plan) {
    if (!wider) {
      wider.emplace(problem, settings.pusher, search, settings.connectivity);
    }
    PushPlan again = wider->plan(from, to);
    again.expansions += plan.expansions;
    again.planning_time_s += plan.planning_time_s;
    plan = std::move(again);
  };
  for (const OrderedPair& pair : interactions.connectivity.pairs) {
    const geometry::Point& from = interactions.connectivity.waypoints[pair.from].position;
    const geometry::Point& to = interactions.connectivity.waypoints[pair.to].position;
    PushPlan plan = planner.plan(from, to);
    if (extends && plan.status == PlanStatus::Exhausted) {
      retry(extended, extendedSearch(settings.search), from, to, plan);
    }
    if (corridor && plan.status == PlanStatus::Exhausted) {
      retry(along_corridor, corridorSearch(settings.search), from, to, plan);
    }
    interactions.plans.push_back(PairPlan{pair, std::move(plan)});
  }
  return interactions;
}

}  // namespace ifar::interaction
