#include "planner/interaction/plan_status.hpp"

#include "planner/interaction/push_plan.hpp"

namespace ifar::interaction {

const char* toString(PlanStatus status)
{
  switch (status) {
    case PlanStatus::Found:
      return "found";
    case PlanStatus::DegeneratePolygon:
      return "degenerate_polygon";
    case PlanStatus::ObjectTooLarge:
      return "object_too_large";
    case PlanStatus::InvalidPhysics:
      return "invalid_physics";
    case PlanStatus::NoStableContact:
      return "no_stable_contact";
    case PlanStatus::TooHeavy:
      return "too_heavy";
    case PlanStatus::UnreachableContact:
      return "unreachable_contact";
    case PlanStatus::InvalidWaypoints:
      return "invalid_waypoints";
    case PlanStatus::ExpansionLimit:
      return "expansion_limit";
    case PlanStatus::TimeBudget:
      return "time_budget";
    case PlanStatus::Exhausted:
      return "exhausted";
  }
  return "unknown";
}

const char* toString(ControlKind kind)
{
  switch (kind) {
    case ControlKind::Straight:
      return "straight";
    case ControlKind::ArcLeft:
      return "arc_left";
    case ControlKind::ArcRight:
      return "arc_right";
    case ControlKind::ContactSwitch:
      return "contact_switch";
  }
  return "unknown";
}

}  // namespace ifar::interaction
