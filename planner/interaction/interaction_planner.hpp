#pragma once
// Problem 2 for one movable object: connectivity analysis, then a push plan for each of the n(n-1)
// ordered waypoint pairs (Algorithm 1, lines 5-9). The DV-graph turns each found plan into a directed
// interaction edge carrying the plan and its cost J.

#include <cstddef>
#include <vector>

#include "planner/interaction/connectivity.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_plan.hpp"

namespace ifar::interaction {

struct PairPlan {
  OrderedPair pair;
  PushPlan plan;
};

struct ObjectInteractions {
  ConnectivityResult connectivity;
  std::vector<PairPlan> plans;  ///< one per ordered pair, in connectivity.pairs order (found or not)
};

ObjectInteractions planObjectInteractions(const LocalScene& scene, std::size_t movable_index,
                                          const ObjectPhysics& physics, const InteractionSettings& settings);

}  // namespace ifar::interaction
