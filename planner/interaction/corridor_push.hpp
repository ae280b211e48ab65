#pragma once
// The corridor push strategy, for an object that fills a corridor (SearchSettings::corridor, built with
// corridorSearch()): from each reachable contact edge one straight push, as far as the object goes
// before it runs into an obstacle or the search radius is spent. The push ends at the first pose where
// the passage is clear and the vehicle standing behind the object reaches at least two stretches of the
// edge of the object's surroundings (wayOnBeyond): where it came from and a way on. So the object may
// close the branch it is pushed into, never the last way on. The cheapest edge's push is the plan: one
// Straight control. Expansions count the way-on judgements.

#include <cstddef>

#include "common/geometry/pose2.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_collision_checker.hpp"
#include "planner/interaction/push_goal_test.hpp"
#include "planner/interaction/push_object.hpp"
#include "planner/interaction/push_plan_assembler.hpp"
#include "planner/interaction/push_strategy.hpp"

namespace ifar::interaction {

class CorridorPush final : public PushStrategy {
 public:
  /// `object`, `checker` and `goal_test` must outlive the strategy; `object` must be Found. `search` is
  /// the corridor search's (its radius is the longest push).
  CorridorPush(const PushObject& object, const PushCollisionChecker& checker, const PushGoalTest& goal_test,
               const SearchSettings& search, const ConnectivitySettings& limits);

  PushPlan solve(const PushProblem& problem, const SearchDeadline& deadline) const override;

 private:
  /// The way-on judgements of one solve and whether the deadline stopped them.
  struct Judgements;

  /// The object pushed straight at `edge` for `step` collision steps.
  geometry::Pose2 poseAt(std::size_t edge, int step) const;
  /// How many collision steps the object goes straight at `edge` before it would run into an obstacle.
  int freeSteps(std::size_t edge, std::size_t depth_side) const;
  /// The first step up to `last` after which the passage is clear and the way on open; 0 for none. The
  /// way on is judged every kCorridorJudgementStepM, then refined back to the first collision step it
  /// holds at: once the object is past a side opening the vehicle behind it keeps reaching that opening,
  /// so no open stretch is skipped.
  int firstOpenStep(std::size_t edge, int last, const PushProblem& problem, Judgements& judgements) const;
  bool opens(std::size_t edge, int step, const PushProblem& problem, Judgements& judgements) const;
  /// The vehicle standing behind the object pushed from `edge` reaches at least two stretches of the edge
  /// of the object's surroundings (where it came from and a way on), or the object stands in the open.
  bool wayOnBeyond(const geometry::Pose2& pose, std::size_t edge) const;

  const PushObject& object_;
  const PushCollisionChecker& checker_;
  const PushGoalTest& goal_test_;
  SearchSettings search_;
  PushPlanAssembler assembler_;
  /// wayOnBeyond looks this far round the object.
  double junction_margin_m_ = 0.0;
};

}  // namespace ifar::interaction
