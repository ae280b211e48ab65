#include "executive/modes/mode.hpp"

namespace ifar::executive {

const char* modeName(Mode mode)
{
  switch (mode) {
    case Mode::Idle:
      return "idle";
    case Mode::Follow:
      return "follow";
    case Mode::Approach:
      return "approach";
    case Mode::Push:
      return "push";
    case Mode::ReplanWait:
      return "replan-wait";
    case Mode::Stop:
      return "stop";
    case Mode::EStop:
      return "e-stop";
    case Mode::Arrived:
      return "arrived";
  }
  return "unknown";
}

std::string describeStale(std::int32_t stale_bits)
{
  std::string text;
  const auto add = [&text](const char* name) {
    if (!text.empty()) {
      text += ", ";
    }
    text += name;
  };
  if ((stale_bits & kStalePose) != 0) {
    add("pose");
  }
  if ((stale_bits & kStalePath) != 0) {
    add("path");
  }
  if ((stale_bits & kStaleForce) != 0) {
    add("force");
  }
  if ((stale_bits & kStaleMotor) != 0) {
    add("motor");
  }
  if ((stale_bits & kStaleObstacles) != 0) {
    add("obstacles");
  }
  return text;
}

}  // namespace ifar::executive
