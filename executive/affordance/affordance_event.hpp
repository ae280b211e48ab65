#pragma once
// What the executive learned about an object by pushing it (paper section VII.B): the daemon publishes
// it as AFFORDANCE (affordance_t) and the planner updates the object's interaction edges.

#include <cstdint>
#include <string>

namespace ifar::executive {

enum class AffordanceReason {
  NoMotion,    ///< did not move under the maximum push force: unpushable
  CostHigher,  ///< measured cost above the plan by more than the threshold
  CostLower,   ///< measured cost below the plan by more than the threshold
  Jammed,      ///< slid below the maximum force, then stopped under it: blocked where it stands, pushable
  /// The vehicle could not get where the plan needs it (a contact not reached, a push held by the guard):
  /// a reachability failure that says nothing of the object, which stays pushable.
  ContactNotReached,
};

const char* affordanceReasonName(AffordanceReason reason);

struct AffordanceEvent {
  std::int64_t object_id = -1;
  bool pushable = true;
  double push_force_n = 0.0;   ///< estimated force to keep the object sliding, newtons
  double affordance = 0.0;     ///< estimated push affordance mu (friction force / weight)
  double planned_cost = 0.0;   ///< J of the plan being executed
  double measured_cost = 0.0;  ///< J measured so far, extrapolated to the whole plan
  AffordanceReason reason = AffordanceReason::NoMotion;
  std::string text;  ///< for people
};

}  // namespace ifar::executive
