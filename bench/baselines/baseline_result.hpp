#pragma once
// What every baseline planner returns for one query: a status value (never an exception), the path
// length in world units and the time spent, plus a reason when it failed.

#include <string>
#include <vector>

#include "common/geometry/point.hpp"

namespace ifar::baselines {

enum class BaselineStatus {
  Solved,        // a path was found (for sampling planners: within the requested factor of the optimum)
  NoPath,        // the planner proved there is none (complete planners only)
  Timeout,       // the time cap ran out first; `length` holds the best path so far, if any
  InvalidStart,  // start blocked, off the map or not finite
  InvalidGoal,
  Error,  // the planner library reported a problem; see `reason`
};

const char* toString(BaselineStatus status);

struct BaselineResult {
  BaselineStatus status = BaselineStatus::NoPath;
  double length = 0.0;        // world units; NaN when no path at all
  double milliseconds = 0.0;  // planner-thread CPU time until the result (sampling: until the target cost)
  double wall_milliseconds = 0.0;  // wall time of the whole call
  std::string reason;              // empty when solved
  std::vector<geometry::Point> path;
  bool solved() const { return status == BaselineStatus::Solved; }
};

}  // namespace ifar::baselines
