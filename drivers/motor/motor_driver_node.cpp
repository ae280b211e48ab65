#include "drivers/motor/motor_driver_node.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "common/time.hpp"
#include "drivers/motor/motor_status_message.hpp"
#include "drivers/motor/odometry_message.hpp"

namespace ifar::motor {
namespace {

VelocityLimits limitsOf(const common::VehicleSettings& vehicle)
{
  return VelocityLimits{vehicle.max_linear_velocity, vehicle.max_angular_velocity,
                        vehicle.max_linear_acceleration, vehicle.max_angular_acceleration};
}

DriveSetup setupOf(const MotorConfig& config, const VelocityLimits& limits)
{
  const double track = config.drive.wheel_track_m;
  const double radius = config.drive.wheel_radius_m;
  const auto acceleration = static_cast<std::uint32_t>(wheelAccelerationLimit(limits, track, radius));
  DriveSetup setup;
  setup.max_velocity = static_cast<std::uint32_t>(wheelVelocityLimit(limits, track, radius));
  setup.acceleration = acceleration;
  setup.deceleration = acceleration;
  // A drive that lost this driver brakes as hard as the vehicle may: the same wheel deceleration.
  setup.quick_stop_deceleration = acceleration;
  setup.master_node_id = config.master_node_id;
  setup.master_heartbeat_timeout_ms = config.drive_heartbeat_timeout_ms;
  setup.rpdo_timeout_ms = config.drive_rpdo_timeout_ms;
  return setup;
}

DifferentialDriveSettings driveSettingsOf(const MotorConfig& config, const DriveSetup& setup)
{
  DifferentialDriveSettings settings = config.drive;
  for (MotorClientSettings* client : {&settings.left, &settings.right}) {
    client->max_velocity = static_cast<std::int32_t>(setup.max_velocity);
    client->configuration = driveConfigurationWrites(setup);
  }
  return settings;
}

std::string seconds(std::int64_t microseconds)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f s", common::microsecondsToSeconds(microseconds));
  return text;
}

}  // namespace

MotorDriverNode::MotorDriverNode(const MotorConfig& config, const common::VehicleSettings& vehicle)
    : config_(config),
      limits_(limitsOf(vehicle)),
      wheel_velocity_limit_(
          motor::wheelVelocityLimit(limits_, config.drive.wheel_track_m, config.drive.wheel_radius_m)),
      drive_setup_(setupOf(config, limits_)),
      drive_(driveSettingsOf(config, drive_setup_)),
      report_limiter_(common::kMicrosecondsPerSecond)
{
}

void MotorDriverNode::refuse(std::int64_t& counter, std::string reason)
{
  ++counter;
  ++refused_since_report_;
  latest_refusal_ = std::move(reason);
}

void MotorDriverNode::onVelocityCommand(const ifar::velocity_cmd_t& command, std::int64_t now_us)
{
  const auto within = withinSpeedLimits({command.linear_velocity, command.angular_velocity}, limits_);
  if (!within) {
    refuse(counters_.non_finite, "not a number: linear " + std::to_string(command.linear_velocity) +
                                     " m/s, angular " + std::to_string(command.angular_velocity) + " rad/s");
    return;
  }
  const std::int64_t age_us = now_us - command.utime;
  if (age_us > config_.drive.left.command_timeout_us) {
    refuse(counters_.stale, "stale: utime " + std::to_string(command.utime) + " is " + seconds(age_us) +
                                " old (limit " + seconds(config_.drive.left.command_timeout_us) + ")");
    return;
  }
  if (-age_us > config_.command_future_tolerance_us) {
    refuse(counters_.future, "from the future: utime " + std::to_string(command.utime) + " is " +
                                 seconds(-age_us) + " ahead of this clock (tolerance " +
                                 seconds(config_.command_future_tolerance_us) + ")");
    return;
  }
  if (has_command_ && command.utime < command_utime_) {
    refuse(counters_.out_of_order, "out of order: utime " + std::to_string(command.utime) + " is " +
                                       seconds(command_utime_ - command.utime) +
                                       " older than a command already taken");
    return;
  }
  ++counters_.accepted;
  if (within->linear != command.linear_velocity || within->angular != command.angular_velocity) {
    ++counters_.limited;
  }
  target_ = *within;
  command_utime_ = command.utime;
  has_command_ = true;
}

void MotorDriverNode::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  drive_.onFrame(frame, now_us);
}

std::vector<can::Frame> MotorDriverNode::heartbeatIfDue(std::int64_t now_us)
{
  if (next_heartbeat_us_ && now_us < *next_heartbeat_us_) {
    return {};
  }
  // Keep the period's grid; after a stall start a new one rather than bursting.
  const std::int64_t period = config_.master_heartbeat_period_us;
  next_heartbeat_us_ = next_heartbeat_us_ && now_us - *next_heartbeat_us_ < period
                           ? *next_heartbeat_us_ + period
                           : now_us + period;
  return {encodeHeartbeat(config_.master_node_id, NmtState::kOperational)};
}

std::vector<can::Frame> MotorDriverNode::cycle(std::int64_t now_us)
{
  const std::int64_t elapsed_us =
      last_cycle_us_ ? std::clamp<std::int64_t>(now_us - *last_cycle_us_, 0, 2 * config_.cycle_us)
                     : config_.cycle_us;
  last_cycle_us_ = now_us;
  // Ramps start from standstill whenever the drives are not running (enabling, stopped, stale).
  output_ = drive_.running(now_us) ? towardWithinAcceleration(
                                         output_, target_, common::microsecondsToSeconds(elapsed_us), limits_)
                                   : BodyVelocity{};
  if (has_command_) {
    // The accepted command's own utime: staleness is judged on when the executive spoke.
    drive_.command(output_.linear, output_.angular, command_utime_);
  }
  std::vector<can::Frame> frames = heartbeatIfDue(now_us);
  const std::vector<can::Frame> drive_frames = drive_.update(now_us);
  frames.insert(frames.end(), drive_frames.begin(), drive_frames.end());
  return frames;
}

std::vector<ifar::motor_status_t> MotorDriverNode::statusMessages(std::int64_t now_us) const
{
  return {toMessage(drive_.leftStatus(now_us), now_us), toMessage(drive_.rightStatus(now_us), now_us)};
}

ifar::odometry_t MotorDriverNode::odometry(std::int64_t now_us) const
{
  const OdometryGeometry geometry{config_.drive.wheel_radius_m, config_.drive.wheel_track_m,
                                  config_.odometry_timeout_us};
  return toOdometryMessage(drive_.leftStatus(now_us), drive_.rightStatus(now_us), now_us, geometry);
}

void MotorDriverNode::stopAndDisable()
{
  target_ = BodyVelocity{};
  output_ = BodyVelocity{};
  drive_.setEnabled(false);
}

std::optional<std::string> MotorDriverNode::takeRefusalReport(std::int64_t now_us)
{
  if (refused_since_report_ == 0 || !report_limiter_.allow(now_us)) {
    return std::nullopt;
  }
  std::string report = "refused " + std::to_string(refused_since_report_) +
                       " velocity command(s) since the last report; the latest: " + latest_refusal_;
  refused_since_report_ = 0;
  return report;
}

std::string MotorDriverNode::readinessProblem(std::int64_t now_us) const
{
  std::string problem;
  const auto add = [&problem](const std::string& text) { problem += (problem.empty() ? "" : "; ") + text; };
  for (const MotorStatus& status : {drive_.leftStatus(now_us), drive_.rightStatus(now_us)}) {
    const std::string drive = "drive " + std::to_string(status.node_id);
    if (!status.heartbeat_ok) {
      add(status.nmt_state ? drive + " heartbeat lost" : "no heartbeat from " + drive + " since start");
    } else if (status.fault_latched) {
      char code[16];
      std::snprintf(code, sizeof(code), "0x%04X", static_cast<unsigned>(status.emergency_code));
      add(drive + " fault, EMCY " + code);
    }
  }
  return problem;
}

std::string MotorDriverNode::takeHealthProblem(std::int64_t now_us)
{
  std::string problem;
  for (const MotorStatus& status : {drive_.leftStatus(now_us), drive_.rightStatus(now_us)}) {
    if (!status.configuration_error.empty() && !status.configured) {
      problem += (problem.empty() ? "" : "; ") + status.configuration_error;
    }
  }
  const std::int64_t refused = counters_.refused() - refused_at_last_health_;
  refused_at_last_health_ = counters_.refused();
  if (refused > 0) {
    problem += (problem.empty() ? "" : "; ") + std::to_string(refused) + " velocity commands refused";
  }
  return problem;
}

}  // namespace ifar::motor
