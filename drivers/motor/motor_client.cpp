#include "drivers/motor/motor_client.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "common/vehicle_model.hpp"

namespace ifar::motor {

const char* toString(ClientPhase phase)
{
  switch (phase) {
    case ClientPhase::kWaitingForDrive:
      return "waiting for drive";
    case ClientPhase::kConfiguring:
      return "configuring";
    case ClientPhase::kEnabling:
      return "enabling";
    case ClientPhase::kRunning:
      return "running";
    case ClientPhase::kStopping:
      return "stopping";
    case ClientPhase::kStopped:
      return "stopped";
  }
  return "unknown";
}

const char* toString(StopReason reason)
{
  switch (reason) {
    case StopReason::kNone:
      return "";
    case StopReason::kNotEnabled:
      return "disabled by operator";
    case StopReason::kStaleCommand:
      return "stale command";
    case StopReason::kHeartbeatLost:
      return "heartbeat lost";
    case StopReason::kDriveFault:
      return "drive fault";
    case StopReason::kConfiguring:
      return "configuring drive";
    case StopReason::kConfigurationFailed:
      return "drive configuration failed";
  }
  return "unknown";
}

namespace {

DriveConfiguratorSettings configuratorSettings(const MotorClientSettings& settings)
{
  return DriveConfiguratorSettings{settings.node_id, settings.configuration, settings.sdo_timeout_us,
                                   settings.sdo_attempts, settings.configuration_retry_us};
}

}  // namespace

MotorClient::MotorClient(const MotorClientSettings& settings)
    : settings_(settings), configurator_(configuratorSettings(settings))
{
}

void MotorClient::latchFault(std::uint16_t code)
{
  fault_latched_ = true;
  fault_reset_pending_ = false;
  if (code != 0) {
    emergency_code_ = code;
  }
}

void MotorClient::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  if (!isFromNode(frame, settings_.node_id)) {
    ++ignored_frames_;
    return;
  }
  const std::uint32_t base = frame.id - settings_.node_id;
  if (base == kHeartbeatBase) {
    const auto state = decodeHeartbeat(frame, settings_.node_id);
    if (!state) {
      ++bad_frames_;
      return;
    }
    nmt_state_ = state;
    last_heartbeat_us_ = now_us;
    if (*state == NmtState::kBootUp) {
      statusword_.reset();  // the drive restarted: what it said before, or was told, no longer holds
      configurator_.restart();
    }
  } else if (base == kTpdo1Base) {
    const auto feedback = decodeTpdo1(frame, settings_.node_id);
    if (!feedback) {
      ++bad_frames_;
      return;
    }
    const bool was_fault = statusword_ && driveStateFromStatusword(*statusword_) == DriveState::kFault;
    const DriveState state = driveStateFromStatusword(feedback->statusword);
    const bool is_fault = state == DriveState::kFault || state == DriveState::kFaultReactionActive;
    // A drive entering fault latches; one already in fault when a reset was requested does not re-latch.
    if (is_fault && !was_fault && !fault_reset_pending_) {
      latchFault(0);
    }
    statusword_ = feedback->statusword;
    actual_velocity_ = feedback->actual_velocity;
    feedback_us_ = now_us;
    nmt_state_ = NmtState::kOperational;  // PDOs only flow from an operational node
  } else if (base == kEmergencyBase) {
    const auto emergency = decodeEmergency(frame, settings_.node_id);
    if (!emergency) {
      ++bad_frames_;
      return;
    }
    onEmergency(*emergency);
  } else if (base == kSdoAnswerBase) {
    const auto answer = decodeSdoAnswer(frame, settings_.node_id);
    if (!answer) {
      ++bad_frames_;
      return;
    }
    configurator_.onAnswer(*answer, now_us);
  }
}

void MotorClient::onEmergency(const Emergency& emergency)
{
  if (emergency.error_code == 0) {
    emergency_code_ = 0;  // "error reset or no error"
  } else if (isCommunicationError(emergency.error_code)) {
    // The drive stopped itself for a lost link (its statusword says where it is now); nothing in the
    // drive is broken, so this clears the way a stale command does.
    emergency_code_ = emergency.error_code;
  } else {
    latchFault(emergency.error_code);
  }
}

void MotorClient::command(std::int32_t target_velocity, std::int64_t now_us)
{
  commanded_velocity_ = target_velocity;
  last_command_us_ = now_us;
}

void MotorClient::requestFaultReset()
{
  fault_latched_ = false;
  fault_reset_pending_ = true;
}

bool MotorClient::heartbeatOk(std::int64_t now_us) const
{
  return nmt_state_.has_value() && now_us - last_heartbeat_us_ <= settings_.heartbeat_timeout_us;
}

bool MotorClient::commandFresh(std::int64_t now_us) const
{
  return last_command_us_.has_value() && now_us - *last_command_us_ <= settings_.command_timeout_us;
}

StopReason MotorClient::stopReason(std::int64_t now_us) const
{
  if (fault_latched_)
    return StopReason::kDriveFault;
  if (!heartbeatOk(now_us))
    return StopReason::kHeartbeatLost;
  if (!configurator_.done())
    return configurator_.failed() ? StopReason::kConfigurationFailed : StopReason::kConfiguring;
  if (!enabled_)
    return StopReason::kNotEnabled;
  if (!commandFresh(now_us))
    return StopReason::kStaleCommand;
  return StopReason::kNone;
}

can::Frame MotorClient::rpdo(std::uint16_t controlword, std::int32_t velocity)
{
  const std::int32_t limit = std::max(settings_.max_velocity, std::int32_t{0});
  velocity = std::clamp(velocity, -limit, limit);
  sent_controlword_ = controlword;
  sent_velocity_ = velocity;
  return encodeRpdo1(settings_.node_id, VelocityCommand{controlword, velocity});
}

std::vector<can::Frame> MotorClient::update(std::int64_t now_us)
{
  std::vector<can::Frame> frames;
  // The configuration is written as soon as the drive is there, commands or not, so the drive watches
  // this driver before anything enables it.
  if (heartbeatOk(now_us)) {
    frames = configurator_.update(now_us);
  }
  const StopReason reason = stopReason(now_us);
  const DriveState drive_state =
      statusword_ ? driveStateFromStatusword(*statusword_) : DriveState::kNotReadyToSwitchOn;
  const std::vector<can::Frame> more =
      reason != StopReason::kNone ? stopFrames(reason, drive_state, now_us) : runFrames(drive_state, now_us);
  frames.insert(frames.end(), more.begin(), more.end());
  return frames;
}

std::vector<can::Frame> MotorClient::stopFrames(StopReason reason, DriveState drive_state,
                                                std::int64_t now_us)
{
  std::vector<can::Frame> frames;
  // A drive found enabled that this client did not enable (say, the motor driver restarted while the
  // drive kept its last target) is stopped too.
  const bool not_started = phase_ == ClientPhase::kWaitingForDrive || phase_ == ClientPhase::kConfiguring;
  const bool found_enabled = not_started && drive_state == DriveState::kOperationEnabled;
  if (phase_ == ClientPhase::kRunning || phase_ == ClientPhase::kEnabling || found_enabled) {
    phase_ = ClientPhase::kStopping;
    stop_started_us_ = now_us;
  }
  const bool configuring = reason == StopReason::kConfiguring || reason == StopReason::kConfigurationFailed;
  if (phase_ == ClientPhase::kWaitingForDrive && configuring) {
    phase_ = ClientPhase::kConfiguring;
  }
  reason_ = reason;
  if (phase_ == ClientPhase::kStopping) {
    const bool standstill = std::abs(actual_velocity_) <= settings_.standstill_velocity;
    const bool still_enabled = drive_state == DriveState::kOperationEnabled;
    if (!still_enabled || standstill || now_us - stop_started_us_ >= settings_.stop_timeout_us) {
      phase_ = ClientPhase::kStopped;
    }
  }
  if (phase_ == ClientPhase::kStopping) {
    frames.push_back(rpdo(kControlEnableOperation, 0));  // brake under control to zero velocity
  } else if (phase_ == ClientPhase::kStopped) {
    frames.push_back(rpdo(kControlShutdown, 0));  // power stage off
  }
  // kWaitingForDrive, kConfiguring: nothing was ever enabled, nothing to stop.
  return frames;
}

std::vector<can::Frame> MotorClient::runFrames(DriveState drive_state, std::int64_t now_us)
{
  std::vector<can::Frame> frames;
  reason_ = StopReason::kNone;
  if (!nmt_state_ || *nmt_state_ != NmtState::kOperational) {
    phase_ = ClientPhase::kWaitingForDrive;
    if (!last_nmt_start_us_ || now_us - *last_nmt_start_us_ >= settings_.nmt_retry_us) {
      frames.push_back(encodeNmt(NmtMessage{NmtCommand::kStart, settings_.node_id}));
      last_nmt_start_us_ = now_us;
    }
    return frames;
  }
  if (!statusword_) {
    phase_ = ClientPhase::kEnabling;  // operational, waiting for the first TPDO1
    return frames;
  }
  switch (drive_state) {
    case DriveState::kFault:
    case DriveState::kFaultReactionActive:
      phase_ = ClientPhase::kEnabling;
      // The drive resets on the rising edge of bit 7: make sure the previous controlword had it clear.
      frames.push_back(rpdo(
          (sent_controlword_ & kControlFaultReset) != 0 ? kControlDisableVoltage : kControlFaultReset, 0));
      break;
    case DriveState::kNotReadyToSwitchOn:
    case DriveState::kSwitchOnDisabled:
      fault_reset_pending_ = false;
      phase_ = ClientPhase::kEnabling;
      frames.push_back(rpdo(kControlShutdown, 0));
      break;
    case DriveState::kReadyToSwitchOn:
      fault_reset_pending_ = false;
      phase_ = ClientPhase::kEnabling;
      frames.push_back(rpdo(kControlSwitchOn, 0));
      break;
    case DriveState::kSwitchedOn:
    case DriveState::kQuickStopActive:
      phase_ = ClientPhase::kEnabling;
      frames.push_back(rpdo(kControlEnableOperation, 0));
      break;
    case DriveState::kOperationEnabled:
      phase_ = ClientPhase::kRunning;
      frames.push_back(rpdo(kControlEnableOperation, commanded_velocity_));
      break;
  }
  return frames;
}

MotorStatus MotorClient::status(std::int64_t now_us) const
{
  MotorStatus result;
  result.node_id = settings_.node_id;
  result.nmt_state = nmt_state_;
  result.heartbeat_ok = heartbeatOk(now_us);
  result.statusword = statusword_;
  result.drive_state = statusword_ ? driveStateFromStatusword(*statusword_) : DriveState::kNotReadyToSwitchOn;
  result.target_velocity = sent_velocity_;
  result.actual_velocity = actual_velocity_;
  result.feedback_us = feedback_us_;
  result.emergency_code = emergency_code_;
  result.fault_latched = fault_latched_;
  result.phase = phase_;
  result.reason = stopReason(now_us);  // as of now_us, even before update() acts on it
  result.configured = configurator_.done();
  result.configuration_error = configurator_.error();
  result.bad_frames = bad_frames_;
  result.ignored_frames = ignored_frames_;
  result.sdo_timeouts = configurator_.timeouts();
  return result;
}

WheelVelocities wheelVelocities(double linear_m_per_s, double angular_rad_per_s, double wheel_track_m,
                                double wheel_radius_m)
{
  const auto toUnits = [wheel_radius_m](double wheel_speed_m_per_s) {
    const double units = wheel_speed_m_per_s / wheel_radius_m * 1000.0;
    const double limit = static_cast<double>(std::numeric_limits<std::int32_t>::max());
    if (!std::isfinite(units) || wheel_radius_m <= 0.0) {
      return std::int32_t{0};
    }
    return static_cast<std::int32_t>(std::lround(std::fmax(-limit, std::fmin(limit, units))));
  };
  const common::RimSpeeds rims = common::rimSpeeds(linear_m_per_s, angular_rad_per_s, wheel_track_m);
  return WheelVelocities{toUnits(rims.left), toUnits(rims.right)};
}

}  // namespace ifar::motor
