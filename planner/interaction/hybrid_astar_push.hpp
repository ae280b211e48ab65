#pragma once
// The general push strategy: hybrid A* (hybrid_astar.hpp) over object pose (x, y, heading, discretised
// for duplicate detection) x contact edge. Actions: stable push primitives of fixed length (straight,
// arcs at the edge's smallest stable radius) and contact switches (drive round the object, no two in a
// row). Heuristic: PushHeuristic; goal: PushGoalTest; plus the analytic expansion, a straight push to the
// goal tried at every root and at regular intervals. The object never leaves the search radius round
// its start, where the onward check's surroundings end.

#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_collision_checker.hpp"
#include "planner/interaction/push_goal_test.hpp"
#include "planner/interaction/push_heuristic.hpp"
#include "planner/interaction/push_object.hpp"
#include "planner/interaction/push_plan_assembler.hpp"
#include "planner/interaction/push_strategy.hpp"

namespace ifar::interaction {

class HybridAStarPush final : public PushStrategy {
 public:
  /// `object`, `checker` and `goal_test` must outlive the strategy; `object` must be Found.
  HybridAStarPush(const PushObject& object, const PushCollisionChecker& checker,
                  const PushGoalTest& goal_test, const SearchSettings& search);

  PushPlan solve(const PushProblem& problem, const SearchDeadline& deadline) const override;

 private:
  const PushObject& object_;
  const PushCollisionChecker& checker_;
  const PushGoalTest& goal_test_;
  PushHeuristic heuristic_;
  SearchSettings search_;
  PushPlanAssembler assembler_;
};

}  // namespace ifar::interaction
