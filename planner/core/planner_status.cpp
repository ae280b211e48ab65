#include "planner/core/planner_status.hpp"

namespace ifar::planner {

const char* toString(PlannerState state)
{
  switch (state) {
    case PlannerState::Idle:
      return "idle";
    case PlannerState::Planning:
      return "planning";
    case PlannerState::NoPath:
      return "no path";
    case PlannerState::Arrived:
      return "arrived";
    case PlannerState::BadInput:
      return "bad input";
  }
  return "unknown";
}

}  // namespace ifar::planner
