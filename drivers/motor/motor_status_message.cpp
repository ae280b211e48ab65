#include "drivers/motor/motor_status_message.hpp"

namespace ifar::motor {
namespace {

std::int8_t driveStateCode(const MotorStatus& status)
{
  if (!status.statusword) {
    return ifar::motor_status_t::DRIVE_NOT_READY;
  }
  switch (status.drive_state) {
    case DriveState::kReadyToSwitchOn:
      return ifar::motor_status_t::DRIVE_READY_TO_SWITCH_ON;
    case DriveState::kSwitchedOn:
      return ifar::motor_status_t::DRIVE_SWITCHED_ON;
    case DriveState::kOperationEnabled:
      return ifar::motor_status_t::DRIVE_OPERATION_ENABLED;
    case DriveState::kFault:
    case DriveState::kFaultReactionActive:
      return ifar::motor_status_t::DRIVE_FAULT;
    case DriveState::kNotReadyToSwitchOn:
    case DriveState::kSwitchOnDisabled:
    case DriveState::kQuickStopActive:
      return ifar::motor_status_t::DRIVE_NOT_READY;
  }
  return ifar::motor_status_t::DRIVE_NOT_READY;
}

}  // namespace

ifar::motor_status_t toMessage(const MotorStatus& status, std::int64_t utime)
{
  ifar::motor_status_t message{};
  message.utime = utime;
  message.node_id = static_cast<std::int8_t>(status.node_id);
  // No heartbeat yet reads as "boot-up" (0), the state a node is in before it reports one.
  message.nmt_state =
      static_cast<std::int8_t>(status.nmt_state ? static_cast<std::uint8_t>(*status.nmt_state) : 0);
  message.heartbeat_ok = status.heartbeat_ok;
  message.statusword = static_cast<std::int16_t>(status.statusword.value_or(0));
  message.drive_state = driveStateCode(status);
  message.target_velocity = status.target_velocity;
  message.actual_velocity = status.actual_velocity;
  message.emergency_code = static_cast<std::int16_t>(status.emergency_code);
  message.reason = toString(status.reason);
  if (status.reason == StopReason::kConfigurationFailed && !status.configuration_error.empty()) {
    message.reason += ": " + status.configuration_error;
  }
  return message;
}

}  // namespace ifar::motor
