#pragma once
// How one push problem is solved (OMPL's planner role): each strategy takes the problem and a deadline
// and returns a plan whose status says whether it found one or why not. Strategies are built once per
// object from its shared parts (PushObject, PushCollisionChecker, PushGoalTest) and are const, so the
// searches of all waypoint pairs share them. Every strategy passes the same contract tests
// (tests/unit/interaction/push_strategy_contract_test.cpp).

#include "planner/interaction/push_plan.hpp"
#include "planner/interaction/push_problem.hpp"
#include "planner/interaction/search_deadline.hpp"

namespace ifar::interaction {

class PushStrategy {
 public:
  PushStrategy() = default;
  PushStrategy(const PushStrategy&) = delete;
  PushStrategy& operator=(const PushStrategy&) = delete;
  virtual ~PushStrategy() = default;

  /// A plan that opens `problem`'s passage (status Found), or why none was found: ExpansionLimit or
  /// TimeBudget when `deadline` ran out, Exhausted when no push of this strategy opens it. Every plan
  /// carries the object's footprint and start pose, the expansions used and the time since the deadline
  /// started.
  virtual PushPlan solve(const PushProblem& problem, const SearchDeadline& deadline) const = 0;
};

}  // namespace ifar::interaction
