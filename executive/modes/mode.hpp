#pragma once
// The executive's modes, as reported in EXEC_STATUS (the values match exec_status_t.MODE_*).

#include <cstdint>
#include <string>

namespace ifar::executive {

enum class Mode : std::int8_t {
  Idle = 0,        ///< no path
  Follow = 1,      ///< collision-free following toward the next waypoint
  Approach = 2,    ///< driving to the contact pose of a push plan
  Push = 3,        ///< executing a push plan with force feedback
  ReplanWait = 4,  ///< affordance reported, waiting for the replanned path
  Stop = 5,        ///< stopped: an input went stale, a fault, or no way to go; see the reason
  EStop = 6,       ///< stopped by an e-stop until released
  Arrived = 7,     ///< at the goal
};

const char* modeName(Mode mode);

/// Which inputs are stale, as bits (the values match exec_status_t.STALE_*).
enum StaleInput : std::int32_t {
  kStalePose = 1,
  kStalePath = 2,
  kStaleForce = 4,
  kStaleMotor = 8,       ///< motor heartbeat lost or motor fault
  kStaleObstacles = 16,  ///< no lidar packet lately: the obstacle points are stale or there are none
};

/// "pose, force" style list of the set bits; empty for 0.
std::string describeStale(std::int32_t stale_bits);

}  // namespace ifar::executive
