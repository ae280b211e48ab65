#pragma once
// The motor driver's node core: everything ifar-motor-driver does between its LCM channels and the CAN
// bus, with neither, so the daemon and the headless simulator runner run the same code. One clock,
// `now_us`, microseconds: the daemon passes the wall clock since the epoch (the clock of
// velocity_cmd_t.utime), the runner simulated epoch time.
//
// - Velocity commands are refused (counted, with a reason for the log) when a speed is NaN or infinite,
//   when their own utime is older than motor.command_timeout_ms or further ahead than
//   motor.command_future_ms (a replayed log or a wrong clock), or older than one already taken.
//   Accepted ones are scaled down to the vehicle's speed limits keeping their curvature
//   (velocity_limits.hpp).
// - Every cycle the output moves toward the last accepted command within the vehicle's accelerations
//   and goes to the two drives (DifferentialDrive): RPDO1 never carries more than the wheel limit,
//   (max_linear_velocity + max_angular_velocity x track / 2) / wheel radius.
// - Each drive is first configured by SDO (its own limits and a watchdog on this driver: drive
//   heartbeat consumer and RPDO deadline, drive_configuration.hpp), and this node produces its CANopen
//   heartbeat (0x700 + motor.master_node_id), so a frozen or dead driver stops the drives by themselves.
//
//   MotorDriverNode node(config, vehicle);
//   on VELOCITY_CMD:            node.onVelocityCommand(message, now_us);
//   on a CAN frame:             node.onFrame(frame, now_us);
//   every motor.cycle_ms:       for (auto& frame : node.cycle(now_us)) bus.send(frame);
//                               publish(ODOMETRY, node.odometry(now_us));
//   every 100 ms:               for (auto& message : node.statusMessages(now_us))
//                                 publish(MOTOR_STATUS, message);
//   on exit:                    node.stopAndDisable(); then keep cycling for a few cycles.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/rate_limiter.hpp"
#include "common/vehicle.hpp"
#include "drivers/can/frame.hpp"
#include "drivers/motor/differential_drive.hpp"
#include "drivers/motor/drive_configuration.hpp"
#include "drivers/motor/motor_config.hpp"
#include "drivers/motor/velocity_limits.hpp"
#include "ifar/motor_status_t.hpp"
#include "ifar/odometry_t.hpp"
#include "ifar/velocity_cmd_t.hpp"

namespace ifar::motor {

/// What became of the velocity commands, since the node started.
struct CommandCounters {
  std::int64_t accepted = 0;      // taken (possibly scaled down)
  std::int64_t limited = 0;       // of them, scaled down to the vehicle's speed limits
  std::int64_t non_finite = 0;    // refused: a speed is NaN or infinite
  std::int64_t stale = 0;         // refused: utime older than the command timeout
  std::int64_t future = 0;        // refused: utime ahead of now by more than the tolerance
  std::int64_t out_of_order = 0;  // refused: older than a command already taken
  std::int64_t refused() const { return non_finite + stale + future + out_of_order; }
};

class MotorDriverNode {
 public:
  /// Throws std::invalid_argument when the drives' node ids are invalid (DifferentialDrive).
  MotorDriverNode(const MotorConfig& config, const common::VehicleSettings& vehicle);

  /// A velocity command as it arrived (its utime on the same clock as `now_us`).
  void onVelocityCommand(const ifar::velocity_cmd_t& command, std::int64_t now_us);
  /// A frame received from the bus (frames for other nodes are counted and skipped by the clients).
  void onFrame(const can::Frame& frame, std::int64_t now_us);
  /// Call every motor.cycle_ms: this driver's heartbeat when due, each drive's SDO configuration, NMT
  /// and RPDO1, in the order to send them.
  std::vector<can::Frame> cycle(std::int64_t now_us);
  /// Call every 100 ms: motor_status_t for the left then the right drive, stamped `now_us`.
  std::vector<ifar::motor_status_t> statusMessages(std::int64_t now_us) const;
  /// Call every motor.cycle_ms (after cycle()): wheel odometry from the drives' last actual velocities
  /// (TPDO1), stamped `now_us`; a drive without TPDO1 for motor.odometry_timeout_ms is flagged stale.
  ifar::odometry_t odometry(std::int64_t now_us) const;

  /// Zero velocity and disable the drives (operator disable, shutdown): keep calling cycle() for a few
  /// cycles so the frames reach them.
  void stopAndDisable();

  /// Both drives run the commanded velocities.
  bool running(std::int64_t now_us) const { return drive_.running(now_us); }
  const CommandCounters& commandCounters() const { return counters_; }
  /// At most once a second, when commands were refused since the last report: how many, and why the
  /// latest was (for the daemon's log).
  std::optional<std::string> takeRefusalReport(std::int64_t now_us);
  /// For the daemon's heartbeat, asked once a beat: what is wrong now (a drive configuration failure)
  /// or since the previous call (refused commands); empty when nothing is.
  std::string takeHealthProblem(std::int64_t now_us);
  /// What the driver waits for, for its heartbeat and log at start-up and after a fault: each drive whose
  /// heartbeat is missing ("drive 1 heartbeat lost", "no heartbeat from drive 2 since start") or that
  /// holds a fault ("drive 1 fault, EMCY 0x8130"), joined by "; "; empty when both can run.
  std::string readinessProblem(std::int64_t now_us) const;

  /// The limits in force: body speeds and accelerations, and per wheel in drive units.
  const VelocityLimits& limits() const { return limits_; }
  std::int32_t wheelVelocityLimit() const { return wheel_velocity_limit_; }
  /// What each drive is configured with at start-up.
  const DriveSetup& driveSetup() const { return drive_setup_; }

 private:
  void refuse(std::int64_t& counter, std::string reason);
  std::vector<can::Frame> heartbeatIfDue(std::int64_t now_us);

  MotorConfig config_;
  VelocityLimits limits_;
  std::int32_t wheel_velocity_limit_ = 0;
  DriveSetup drive_setup_;
  DifferentialDrive drive_;

  bool has_command_ = false;
  std::int64_t command_utime_ = 0;  // utime of the last accepted command
  BodyVelocity target_;             // the last accepted command, within the speed limits
  BodyVelocity output_;             // what goes to the drives, within the accelerations
  std::optional<std::int64_t> last_cycle_us_;
  std::optional<std::int64_t> next_heartbeat_us_;

  CommandCounters counters_;
  std::int64_t refused_since_report_ = 0;
  std::int64_t refused_at_last_health_ = 0;
  std::string latest_refusal_;
  common::RateLimiter report_limiter_;
};

}  // namespace ifar::motor
