#include "drivers/motor/drive_emulator.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::motor {
namespace {

// CiA 402 controlword commands, by the bits that decide them.
bool isShutdown(std::uint16_t controlword)
{
  return (controlword & 0x87) == 0x06;
}
bool isSwitchOn(std::uint16_t controlword)
{
  return (controlword & 0x8F) == 0x07;
}
bool isEnableOperation(std::uint16_t controlword)
{
  return (controlword & 0x8F) == 0x0F;
}
bool isDisableVoltage(std::uint16_t controlword)
{
  return (controlword & 0x82) == 0x00;
}
bool isQuickStop(std::uint16_t controlword)
{
  return (controlword & 0x86) == 0x02;
}

constexpr std::uint8_t kGenericErrorRegister = 0x01;

}  // namespace

DriveEmulator::DriveEmulator(const DriveEmulatorSettings& settings) : settings_(settings) {}

std::int32_t DriveEmulator::commandedVelocity() const
{
  return drive_state_ == DriveState::kOperationEnabled ? target_velocity_ : 0;
}

void DriveEmulator::resetNode()
{
  boot_up_pending_ = true;
  nmt_state_ = NmtState::kBootUp;
  drive_state_ = DriveState::kSwitchOnDisabled;
  fault_code_ = 0;
  target_velocity_ = 0;
  last_controlword_ = 0;
}

void DriveEmulator::onFrame(const can::Frame& frame, std::int64_t /*now_us*/)
{
  if (frame.error() || frame.extended() || frame.remote()) {
    return;
  }
  if (frame.id == kNmtId) {
    const auto message = decodeNmt(frame);
    if (!message) {
      ++bad_frames_;
      return;
    }
    if (message->node_id != 0 && message->node_id != settings_.node_id) {
      return;
    }
    const NmtState before = nmt_state_;
    switch (message->command) {
      case NmtCommand::kStart:
        nmt_state_ = NmtState::kOperational;
        break;
      case NmtCommand::kStop:
        nmt_state_ = NmtState::kStopped;
        break;
      case NmtCommand::kEnterPreOperational:
        nmt_state_ = NmtState::kPreOperational;
        break;
      case NmtCommand::kResetNode:
        resetNode();
        return;
      case NmtCommand::kResetCommunication:
        boot_up_pending_ = true;
        nmt_state_ = NmtState::kBootUp;
        break;
    }
    // Leaving operational ends PDO control: the drive stops its power stage, as CiA 402 drives do
    // on a communication loss (object 0x6007 "disable voltage").
    if (before == NmtState::kOperational && nmt_state_ != NmtState::kOperational &&
        drive_state_ != DriveState::kFault) {
      drive_state_ = DriveState::kSwitchOnDisabled;
      target_velocity_ = 0;
    }
    return;
  }
  if (frame.id != kRpdo1Base + settings_.node_id) {
    return;
  }
  const auto command = decodeRpdo1(frame, settings_.node_id);
  if (!command) {
    ++bad_frames_;
    return;
  }
  if (nmt_state_ != NmtState::kOperational) {
    return;  // PDOs are only processed when operational
  }
  target_velocity_ = command->target_velocity;
  applyControlword(command->controlword);
}

void DriveEmulator::applyControlword(std::uint16_t controlword)
{
  const bool reset_edge = (controlword & 0x80) != 0 && (last_controlword_ & 0x80) == 0;
  last_controlword_ = controlword;
  switch (drive_state_) {
    case DriveState::kFault:
    case DriveState::kFaultReactionActive:
      if (reset_edge) {
        drive_state_ = DriveState::kSwitchOnDisabled;
        fault_code_ = 0;
        pending_emergencies_.push_back(Emergency{0x0000, 0x00, settings_.node_id});
      }
      return;
    case DriveState::kNotReadyToSwitchOn:
    case DriveState::kSwitchOnDisabled:
      if (isShutdown(controlword))
        drive_state_ = DriveState::kReadyToSwitchOn;
      return;
    case DriveState::kReadyToSwitchOn:
      if (isSwitchOn(controlword) || isEnableOperation(controlword)) {
        drive_state_ = DriveState::kSwitchedOn;
      } else if (isDisableVoltage(controlword) || isQuickStop(controlword)) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      }
      return;
    case DriveState::kSwitchedOn:
      if (isEnableOperation(controlword)) {
        drive_state_ = DriveState::kOperationEnabled;
      } else if (isShutdown(controlword)) {
        drive_state_ = DriveState::kReadyToSwitchOn;
      } else if (isDisableVoltage(controlword) || isQuickStop(controlword)) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      }
      return;
    case DriveState::kOperationEnabled:
      if (isSwitchOn(controlword)) {
        drive_state_ = DriveState::kSwitchedOn;
      } else if (isShutdown(controlword)) {
        drive_state_ = DriveState::kReadyToSwitchOn;
      } else if (isDisableVoltage(controlword)) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      } else if (isQuickStop(controlword)) {
        drive_state_ = DriveState::kQuickStopActive;
      }
      return;
    case DriveState::kQuickStopActive:
      if (isEnableOperation(controlword)) {
        drive_state_ = DriveState::kOperationEnabled;
      } else if (isDisableVoltage(controlword)) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      }
      return;
  }
}

void DriveEmulator::injectFault(std::uint16_t error_code)
{
  drive_state_ = DriveState::kFault;
  fault_code_ = error_code;
  pending_emergencies_.push_back(Emergency{error_code, kGenericErrorRegister, settings_.node_id});
}

std::vector<can::Frame> DriveEmulator::update(std::int64_t now_us)
{
  if (settings_.model_velocity && last_update_us_ >= 0 && now_us > last_update_us_) {
    const double seconds = static_cast<double>(now_us - last_update_us_) * 1e-6;
    const double allowed = settings_.acceleration * seconds;
    const double step =
        std::clamp(static_cast<double>(commandedVelocity()) - modelled_velocity_, -allowed, allowed);
    modelled_velocity_ += step;
    actual_velocity_ = static_cast<std::int32_t>(std::lround(modelled_velocity_));
  }
  last_update_us_ = now_us;
  if (drive_state_ == DriveState::kQuickStopActive && actual_velocity_ == 0) {
    drive_state_ = DriveState::kSwitchOnDisabled;
  }

  std::vector<can::Frame> frames;
  if (!transmitting_) {
    pending_emergencies_.clear();
    return frames;
  }
  if (boot_up_pending_) {
    frames.push_back(encodeHeartbeat(settings_.node_id, NmtState::kBootUp));
    boot_up_pending_ = false;
    if (nmt_state_ == NmtState::kBootUp) {
      nmt_state_ = NmtState::kPreOperational;  // boot-up ends in pre-operational by itself
    }
    next_heartbeat_us_ = now_us + settings_.heartbeat_period_us;
  }
  for (const Emergency& emergency : pending_emergencies_) {
    frames.push_back(encodeEmergency(emergency));
  }
  pending_emergencies_.clear();
  if (now_us >= next_heartbeat_us_) {
    if (heartbeat_enabled_) {
      frames.push_back(encodeHeartbeat(settings_.node_id, nmt_state_));
    }
    next_heartbeat_us_ = now_us + settings_.heartbeat_period_us;
  }
  if (nmt_state_ == NmtState::kOperational && now_us >= next_tpdo_us_) {
    frames.push_back(encodeTpdo1(settings_.node_id, VelocityFeedback{statusword(), actual_velocity_}));
    next_tpdo_us_ = now_us + settings_.tpdo_period_us;
  }
  return frames;
}

}  // namespace ifar::motor
