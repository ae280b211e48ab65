#pragma once
// The executive node's conversions between LCM messages and the library's plain structs. Only the node
// core (executive_node.hpp) and its tests include this: the library itself never sees LCM messages.

#include <cstdint>
#include <map>
#include <optional>

#include "executive/modes/executive.hpp"
#include "executive/modes/inputs.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/e_stop_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/force_t.hpp"
#include "ifar/motor_status_t.hpp"
#include "ifar/odometry_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velocity_cmd_t.hpp"

namespace ifar::executive {

/// Position and yaw (heading) of a pose_t; the quaternion need not be normalised.
geometry::Pose2 fromMessage(const ifar::pose_t& message);

/// The path with its push plans. Waypoints and controls of unknown kind are counted in `malformed`:
/// such a waypoint becomes free, such a control is dropped.
Path fromMessage(const ifar::path_t& message, int& malformed);

/// Fault, silent and stuck-counter statuses make the reading faulty; overload keeps the (saturated) value.
ForceReading fromMessage(const ifar::force_t& message);

/// The body velocity; invalid when the driver flags either drive's actual velocity stale.
OdometryReading fromMessage(const ifar::odometry_t& message);

EStopSignal fromMessage(const ifar::e_stop_t& message);

/// Combines the MOTOR_STATUS reports of every drive node into one reading: healthy only when every node
/// seen has a heartbeat and no fault; stamped with the oldest node's receive time, so one silent node
/// makes the whole motor stale.
class MotorStatusCombiner {
 public:
  void update(const ifar::motor_status_t& message, std::int64_t receive_utime);
  std::optional<Stamped<MotorReading>> combined() const;

 private:
  struct NodeState {
    MotorReading reading;
    std::int64_t utime = 0;
  };
  std::map<int, NodeState> nodes_;
};

ifar::velocity_cmd_t toVelocityMessage(const Output& output, std::int64_t utime);
ifar::exec_status_t toStatusMessage(const Output& output, std::int64_t utime);
ifar::affordance_t toAffordanceMessage(const AffordanceEvent& event, std::int64_t utime);
ifar::blocked_passage_t toBlockedPassageMessage(const BlockedPassage& passage, std::int64_t utime);

}  // namespace ifar::executive
