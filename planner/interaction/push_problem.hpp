#pragma once
// One push search's problem (paper VI.C, Problem 3): the object (PushObject, shared by all waypoint
// pairs), the contacts the vehicle can start from, and the goal region between two waypoints.

#include <cstddef>
#include <vector>

#include "common/geometry/point.hpp"
#include "planner/interaction/plan_status.hpp"
#include "planner/interaction/push_collision_checker.hpp"
#include "planner/interaction/push_goal_region.hpp"
#include "planner/interaction/push_goal_test.hpp"
#include "planner/interaction/push_object.hpp"

namespace ifar::interaction {

/// A contact edge the vehicle reaches from the start waypoint in a straight line.
struct PushContact {
  std::size_t edge = 0;
  double approach_m = 0.0;  ///< from the start waypoint to the edge's standing point
};

struct PushProblem {
  geometry::Point start;  ///< topological waypoint the vehicle comes from
  geometry::Point goal;   ///< topological waypoint it must reach past the object
  PushGoalRegion goal_region;
  std::vector<PushContact> contacts;  ///< never empty
  /// An object seen only as a face: its depth lies beyond the face as seen from the start waypoint, on
  /// this side (PushCollisionChecker::objectCollides) and in this direction (body frame, turnConfined).
  std::size_t depth_side = 0;
  geometry::Vector depth_direction = geometry::Vector::UnitY();
};

struct PushProblemResult {
  /// Found with `problem` set; InvalidWaypoints (not finite, coincident or inside an obstacle) or
  /// UnreachableContact (no stable contact edge in sight of the start waypoint) otherwise.
  PlanStatus status = PlanStatus::Found;
  PushProblem problem;
};

/// The problem of pushing `object` (status Found) so the passage from `start` to `goal` opens.
PushProblemResult makePushProblem(const PushObject& object, const PushCollisionChecker& checker,
                                  const PushGoalTest& goal_test, const geometry::Point& start,
                                  const geometry::Point& goal);

}  // namespace ifar::interaction
