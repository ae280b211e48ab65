#include "bench/scenarios/driven_outcome.hpp"

#include <cmath>

namespace ifar::scenarios {

std::string drivenStatus(bool arrived, const std::string& reason, bool far_mode, double without_pushing)
{
  if (arrived) {
    return "arrived";
  }
  // The runner appends the planner's no-path message only while the planner has no path.
  if (reason.find("; planner: ") != std::string::npos) {
    return far_mode && !std::isfinite(without_pushing) ? "no_path_pushing_required" : "no_path";
  }
  if (reason.rfind("timeout after", 0) == 0) {
    return "time_limit";
  }
  return "failed";
}

bool correctOutcome(const std::string& status)
{
  return status == "arrived" || status == "no_path_pushing_required";
}

}  // namespace ifar::scenarios
