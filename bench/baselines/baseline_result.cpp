#include "bench/baselines/baseline_result.hpp"

namespace ifar::baselines {

const char* toString(BaselineStatus status)
{
  switch (status) {
    case BaselineStatus::Solved:
      return "solved";
    case BaselineStatus::NoPath:
      return "no_path";
    case BaselineStatus::Timeout:
      return "timeout";
    case BaselineStatus::InvalidStart:
      return "invalid_start";
    case BaselineStatus::InvalidGoal:
      return "invalid_goal";
    case BaselineStatus::Error:
      return "error";
  }
  return "unknown";
}

}  // namespace ifar::baselines
