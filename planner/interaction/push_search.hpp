#pragma once
// The push search for one object (paper VI.C, Problem 3), in roles: the object (push_object.hpp), a const
// collision checker (push_collision_checker.hpp), the goal test and goal region (push_goal_test.hpp), the
// problem of one waypoint pair (push_problem.hpp), and a strategy that solves it against a deadline
// (push_strategy.hpp): hybrid A* (hybrid_astar_push.hpp over the generic hybrid_astar.hpp) or, with
// SearchSettings::corridor (corridorSearch()), the corridor push (corridor_push.hpp).
//
// A PushPlanner is built once per object and answers the n(n-1) waypoint pairs; plan() is const.

#include <memory>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/object_model.hpp"
#include "planner/interaction/plan_status.hpp"
#include "planner/interaction/push_collision_checker.hpp"
#include "planner/interaction/push_goal_test.hpp"
#include "planner/interaction/push_object.hpp"
#include "planner/interaction/push_plan.hpp"
#include "planner/interaction/push_problem.hpp"
#include "planner/interaction/push_strategy.hpp"
#include "planner/interaction/stable_push.hpp"

namespace ifar::interaction {

class PushPlanner {
 public:
  PushPlanner(const PushProblemObject& problem, const PusherSettings& pusher, const SearchSettings& search,
              const ConnectivitySettings& limits);
  /// The strategy refers to the parts this object owns: neither copied nor moved.
  PushPlanner(const PushPlanner&) = delete;
  PushPlanner& operator=(const PushPlanner&) = delete;
  ~PushPlanner();

  /// Found when the object can be planned for; otherwise every plan() returns this status.
  PlanStatus status() const { return object_.status(); }
  const ObjectModel& model() const { return object_.model(); }
  const std::vector<EdgePushOptions>& edgeOptions() const { return object_.edgeOptions(); }

  /// Searches a push plan that opens the passage from `start` to `goal` (topological waypoints), within
  /// the search's time budget and expansion limit (the corridor push has neither: it is the last resort
  /// for a pair both searches proved impossible, and its work is bounded by its length).
  PushPlan plan(const geometry::Point& start, const geometry::Point& goal) const;

  /// The problem plan() poses for `start` -> `goal`; the object's status when that is not Found.
  PushProblemResult problem(const geometry::Point& start, const geometry::Point& goal) const;
  /// The parts plan() uses, for tests that hold each strategy to the same contract; only when status()
  /// is Found.
  const PushStrategy& strategy() const { return *strategy_; }
  const PushObject& object() const { return object_; }
  const PushCollisionChecker& collisionChecker() const { return *checker_; }
  const PushGoalTest& goalTest() const { return *goal_test_; }

 private:
  SearchSettings search_;
  PushObject object_;
  std::optional<PushCollisionChecker> checker_;
  std::optional<PushGoalTest> goal_test_;
  std::unique_ptr<PushStrategy> strategy_;
};

}  // namespace ifar::interaction
