#include "sim/can_nodes/drive_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "drivers/motor/sdo.hpp"

namespace ifar::sim {
namespace {

using motor::DriveState;
using motor::NmtState;

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

constexpr std::uint8_t kGenericErrorRegister = 0x01;        // object 0x1001 bit 0
constexpr std::uint8_t kCommunicationErrorRegister = 0x10;  // bit 4
constexpr unsigned kHeartbeatErrorBit = 1;
constexpr unsigned kRpdoErrorBit = 2;
constexpr std::int32_t kStandstill = 20;  // |actual| at or below this (0.001 rad/s) ends a quick stop
constexpr std::uint32_t kUnlimited = std::numeric_limits<std::uint32_t>::max();

bool powered(DriveState state)
{
  return state == DriveState::kOperationEnabled || state == DriveState::kQuickStopActive;
}

}  // namespace

DriveEmulator::DriveEmulator(const DriveEmulatorSettings& settings) : settings_(settings) {}

std::int32_t DriveEmulator::commandedVelocity() const
{
  if (drive_state_ != DriveState::kOperationEnabled) {
    return 0;
  }
  const auto limit = static_cast<std::int32_t>(
      std::min<std::uint32_t>(objects_.max_profile_velocity, std::numeric_limits<std::int32_t>::max()));
  return std::clamp(target_velocity_, -limit, limit);
}

std::int32_t DriveEmulator::velocityDemand() const
{
  const bool no_ramp = objects_.profile_acceleration == kUnlimited &&
                       objects_.profile_deceleration == kUnlimited &&
                       objects_.quick_stop_deceleration == kUnlimited;
  if (no_ramp || !powered(drive_state_)) {
    return commandedVelocity();
  }
  return static_cast<std::int32_t>(std::lround(demand_));
}

void DriveEmulator::resetNode()
{
  boot_up_pending_ = true;
  nmt_state_ = NmtState::kBootUp;
  drive_state_ = DriveState::kSwitchOnDisabled;
  fault_code_ = 0;
  target_velocity_ = 0;
  demand_ = 0.0;
  last_controlword_ = 0;
  objects_ = DriveObjects{};  // what was written by SDO is volatile
  heartbeat_watched_ = false;
  rpdo_watched_ = false;
  communication_errors_ = 0;
}

void DriveEmulator::abortConnection()
{
  switch (objects_.abort_connection_option) {
    case motor::kAbortConnectionFault:
      drive_state_ = DriveState::kFault;
      break;
    case motor::kAbortConnectionDisableVoltage:
      if (drive_state_ != DriveState::kFault && drive_state_ != DriveState::kFaultReactionActive) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      }
      break;
    case motor::kAbortConnectionQuickStop:
      if (drive_state_ == DriveState::kOperationEnabled) {
        drive_state_ = DriveState::kQuickStopActive;
      } else if (drive_state_ == DriveState::kReadyToSwitchOn || drive_state_ == DriveState::kSwitchedOn) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      }
      break;
    default:
      break;
  }
}

void DriveEmulator::leaveOperational(NmtState next)
{
  const NmtState before = nmt_state_;
  nmt_state_ = next;
  if (before == NmtState::kOperational && next != NmtState::kOperational) {
    // Leaving operational ends PDO control: the drive reacts as to a lost connection (0x6007).
    rpdo_watched_ = false;
    target_velocity_ = 0;
    abortConnection();
  }
}

void DriveEmulator::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  if (frame.error() || frame.extended() || frame.remote()) {
    return;
  }
  if (frame.id == motor::kNmtId) {
    onNmt(frame);
  } else if (frame.id == motor::kRpdo1Base + settings_.node_id) {
    onRpdo(frame, now_us);
  } else if (frame.id == motor::kSdoRequestBase + settings_.node_id) {
    onSdo(frame);
  } else if (objects_.heartbeatTimeoutUs() > 0 &&
             frame.id == motor::kHeartbeatBase + objects_.watchedNode() &&
             motor::decodeHeartbeat(frame, objects_.watchedNode())) {
    onWatchedHeartbeat(now_us);
  }
}

void DriveEmulator::onNmt(const can::Frame& frame)
{
  const auto message = motor::decodeNmt(frame);
  if (!message) {
    ++bad_frames_;
    return;
  }
  if (message->node_id != 0 && message->node_id != settings_.node_id) {
    return;
  }
  switch (message->command) {
    case motor::NmtCommand::kStart:
      nmt_state_ = NmtState::kOperational;
      break;
    case motor::NmtCommand::kStop:
      leaveOperational(NmtState::kStopped);
      break;
    case motor::NmtCommand::kEnterPreOperational:
      leaveOperational(NmtState::kPreOperational);
      break;
    case motor::NmtCommand::kResetNode:
      leaveOperational(NmtState::kBootUp);
      resetNode();
      break;
    case motor::NmtCommand::kResetCommunication: {
      leaveOperational(NmtState::kBootUp);
      boot_up_pending_ = true;
      // The communication objects (0x1000-0x1FFF) return to their defaults, the drive's keep theirs.
      const DriveObjects defaults;
      objects_.communication_error_behaviour = defaults.communication_error_behaviour;
      objects_.consumer_heartbeat = defaults.consumer_heartbeat;
      objects_.rpdo_event_timer_ms = defaults.rpdo_event_timer_ms;
      heartbeat_watched_ = false;
      break;
    }
  }
}

void DriveEmulator::onRpdo(const can::Frame& frame, std::int64_t now_us)
{
  const auto command = motor::decodeRpdo1(frame, settings_.node_id);
  if (!command) {
    ++bad_frames_;
    return;
  }
  if (nmt_state_ != NmtState::kOperational) {
    return;  // PDOs are only processed when operational
  }
  last_rpdo_us_ = now_us;
  if (objects_.rpdoTimeoutUs() > 0) {
    communicationRestored(kRpdoErrorBit);
    rpdo_watched_ = true;
  }
  target_velocity_ = command->target_velocity;
  applyControlword(command->controlword);
}

void DriveEmulator::onSdo(const can::Frame& frame)
{
  if (nmt_state_ == NmtState::kStopped) {
    return;  // no SDO in stopped
  }
  const auto request = motor::decodeSdoRequest(frame, settings_.node_id);
  if (!request) {
    ++bad_frames_;
    return;
  }
  const std::uint32_t answer_id = motor::kSdoAnswerBase + settings_.node_id;
  switch (request->kind) {
    case motor::SdoRequest::Kind::kAbort:
      return;  // an expedited download has nothing in flight to cancel
    case motor::SdoRequest::Kind::kUnsupported:
      pending_sdo_answers_.push_back(motor::encodeSdoAbort(answer_id, request->write.index,
                                                           request->write.subindex, motor::kAbortBadCommand));
      return;
    case motor::SdoRequest::Kind::kDownload:
      break;
  }
  const std::uint32_t abort_code = writeDriveObject(objects_, request->write);
  pending_sdo_answers_.push_back(
      abort_code == 0
          ? motor::encodeSdoDownloadConfirmed(settings_.node_id, request->write.index,
                                              request->write.subindex)
          : motor::encodeSdoAbort(answer_id, request->write.index, request->write.subindex, abort_code));
  if (request->write.index == motor::kObjectConsumerHeartbeatTime) {
    heartbeat_watched_ = false;  // a new entry is watched from the producer's next heartbeat on
  }
}

void DriveEmulator::onWatchedHeartbeat(std::int64_t now_us)
{
  last_watched_heartbeat_us_ = now_us;
  communicationRestored(kHeartbeatErrorBit);
  heartbeat_watched_ = true;
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
        pending_emergencies_.push_back(motor::Emergency{0x0000, 0x00, settings_.node_id});
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
      // Quick stop option 2: the stop runs to its end in switch on disabled; enable operation does not
      // bring the drive back, only disable voltage ends the stop early.
      if (isDisableVoltage(controlword)) {
        drive_state_ = DriveState::kSwitchOnDisabled;
      }
      return;
  }
}

void DriveEmulator::injectFault(std::uint16_t error_code)
{
  drive_state_ = DriveState::kFault;
  fault_code_ = error_code;
  pending_emergencies_.push_back(motor::Emergency{error_code, kGenericErrorRegister, settings_.node_id});
}

void DriveEmulator::communicationError(std::uint16_t error_code, unsigned error_bit)
{
  communication_errors_ |= error_bit;
  pending_emergencies_.push_back(motor::Emergency{
      error_code, static_cast<std::uint8_t>(kGenericErrorRegister | kCommunicationErrorRegister),
      settings_.node_id});
  const DriveState before = drive_state_;
  abortConnection();
  if (drive_state_ == DriveState::kFault && before != DriveState::kFault) {
    fault_code_ = error_code;
  }
  if (objects_.communication_error_behaviour == motor::kCommunicationErrorPreOperational &&
      nmt_state_ == NmtState::kOperational) {
    leaveOperational(NmtState::kPreOperational);
  } else if (objects_.communication_error_behaviour == motor::kCommunicationErrorStopped) {
    leaveOperational(NmtState::kStopped);
  }
}

void DriveEmulator::communicationRestored(unsigned error_bit)
{
  if ((communication_errors_ & error_bit) == 0) {
    return;
  }
  communication_errors_ &= ~error_bit;
  if (communication_errors_ == 0 && drive_state_ != DriveState::kFault) {
    pending_emergencies_.push_back(motor::Emergency{0x0000, 0x00, settings_.node_id});  // error reset
  }
}

void DriveEmulator::checkWatchdogs(std::int64_t now_us)
{
  const std::int64_t heartbeat_timeout = objects_.heartbeatTimeoutUs();
  if (heartbeat_timeout > 0 && heartbeat_watched_ &&
      now_us - last_watched_heartbeat_us_ > heartbeat_timeout) {
    heartbeat_watched_ = false;  // watched again from the next heartbeat on
    communicationError(motor::kEmergencyHeartbeatError, kHeartbeatErrorBit);
  }
  const std::int64_t rpdo_timeout = objects_.rpdoTimeoutUs();
  if (rpdo_timeout > 0 && rpdo_watched_ && nmt_state_ == NmtState::kOperational &&
      now_us - last_rpdo_us_ > rpdo_timeout) {
    rpdo_watched_ = false;
    communicationError(motor::kEmergencyRpdoTimeout, kRpdoErrorBit);
  }
}

void DriveEmulator::advanceVelocity(std::int64_t now_us)
{
  const double seconds = last_update_us_ >= 0 && now_us > last_update_us_
                             ? static_cast<double>(now_us - last_update_us_) * 1e-6
                             : 0.0;
  if (!powered(drive_state_)) {
    demand_ = 0.0;  // power stage off: the wheel coasts, nothing is demanded
  } else {
    const double target = commandedVelocity();
    const bool speeding_up = std::abs(target) > std::abs(demand_) && target * demand_ >= 0.0;
    const std::uint32_t rate = drive_state_ == DriveState::kQuickStopActive ? objects_.quick_stop_deceleration
                               : speeding_up                                ? objects_.profile_acceleration
                                                                            : objects_.profile_deceleration;
    const double step = static_cast<double>(rate) * seconds;
    demand_ = rate == kUnlimited ? target : demand_ + std::clamp(target - demand_, -step, step);
  }
  if (settings_.model_velocity && seconds > 0.0) {
    const double allowed = settings_.acceleration * seconds;
    modelled_velocity_ +=
        std::clamp(static_cast<double>(velocityDemand()) - modelled_velocity_, -allowed, allowed);
    actual_velocity_ = static_cast<std::int32_t>(std::lround(modelled_velocity_));
  }
  if (drive_state_ == DriveState::kQuickStopActive && velocityDemand() == 0 &&
      std::abs(actual_velocity_) <= kStandstill) {
    drive_state_ = DriveState::kSwitchOnDisabled;  // quick stop option 2: stopped, power stage off
  }
}

void DriveEmulator::emit(std::vector<can::Frame>& frames, std::int64_t now_us)
{
  if (boot_up_pending_) {
    frames.push_back(motor::encodeHeartbeat(settings_.node_id, NmtState::kBootUp));
    boot_up_pending_ = false;
    if (nmt_state_ == NmtState::kBootUp) {
      nmt_state_ = NmtState::kPreOperational;  // boot-up ends in pre-operational by itself
    }
    next_heartbeat_us_ = now_us + settings_.heartbeat_period_us;
  }
  for (const motor::Emergency& emergency : pending_emergencies_) {
    frames.push_back(motor::encodeEmergency(emergency));
  }
  frames.insert(frames.end(), pending_sdo_answers_.begin(), pending_sdo_answers_.end());
  if (now_us >= next_heartbeat_us_) {
    if (heartbeat_enabled_) {
      frames.push_back(motor::encodeHeartbeat(settings_.node_id, nmt_state_));
    }
    next_heartbeat_us_ = now_us + settings_.heartbeat_period_us;
  }
  if (nmt_state_ == NmtState::kOperational && now_us >= next_tpdo_us_) {
    frames.push_back(
        motor::encodeTpdo1(settings_.node_id, motor::VelocityFeedback{statusword(), actual_velocity_}));
    next_tpdo_us_ = now_us + settings_.tpdo_period_us;
  }
}

std::vector<can::Frame> DriveEmulator::update(std::int64_t now_us)
{
  checkWatchdogs(now_us);
  advanceVelocity(now_us);
  last_update_us_ = now_us;
  std::vector<can::Frame> frames;
  if (transmitting_) {
    emit(frames, now_us);
  }
  pending_emergencies_.clear();
  pending_sdo_answers_.clear();
  return frames;
}

}  // namespace ifar::sim
