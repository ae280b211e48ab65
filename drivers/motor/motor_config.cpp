#include "drivers/motor/motor_config.hpp"

namespace ifar::motor {
namespace {

using Range = common::ParameterRange;

common::ParameterTable<MotorSection> makeMotorParameters()
{
  using S = MotorSection;
  const Range milliseconds = Range::atLeast(1);
  auto table =
      common::ParameterTable<S>()
          .add("left_node_id", &S::left_node_id, "", Range::between(1, 127),
               "CANopen node of the left wheel drive")
          .required()
          .add("right_node_id", &S::right_node_id, "", Range::between(1, 127),
               "CANopen node of the right wheel drive")
          .required()
          .add("master_node_id", &S::master_node_id, "", Range::between(1, 127),
               "ifar-motor-driver's own node id: its heartbeat is 0x700 + this, watched by the drives")
          .add("master_heartbeat_ms", &S::master_heartbeat_ms, "ms", milliseconds,
               "ifar-motor-driver's heartbeat period")
          .add("cycle_ms", &S::cycle_ms, "ms", milliseconds, "RPDO1 (velocity command) period")
          .add("heartbeat_timeout_ms", &S::heartbeat_timeout_ms, "ms", milliseconds,
               "a drive silent this long is lost (the drives produce a heartbeat every 100 ms)")
          .add("command_timeout_ms", &S::command_timeout_ms, "ms", milliseconds,
               "a velocity command older than this by its own utime is refused or stale: safe stop")
          .add("command_future_ms", &S::command_future_ms, "ms", milliseconds,
               "a velocity command stamped further ahead than this (a wrong clock) is refused")
          .add("stop_timeout_ms", &S::stop_timeout_ms, "ms", milliseconds,
               "zero velocity at most this long before the drive is disabled")
          .add("sdo_timeout_ms", &S::sdo_timeout_ms, "ms", milliseconds,
               "start-up configuration: an SDO answer later than this is a timeout ...")
          .add("sdo_attempts", &S::sdo_attempts, "", Range::between(1, 100),
               "... repeated this often, then the whole configuration starts over after 1 s")
          .add("drive_watchdog.heartbeat_timeout_ms", &S::drive_heartbeat_timeout_ms, "ms",
               Range::between(0, 65535),
               "written into each drive (0x1016): it quick-stops by itself without this driver's heartbeat "
               "this "
               "long (0: off; longer than master_heartbeat_ms)")
          .add("drive_watchdog.rpdo_timeout_ms", &S::drive_rpdo_timeout_ms, "ms", Range::between(0, 65535),
               "written into each drive (0x1400 sub 5): it quick-stops without an RPDO1 this long (0: off; "
               "longer than cycle_ms)")
          .add("status_channel", &S::status_channel, "", Range::nonEmpty(), "motor_status_t")
          .add("odometry_timeout_ms", &S::odometry_timeout_ms, "ms", milliseconds,
               "a drive without a TPDO1 (actual velocity, 100 Hz) this long is flagged stale in odometry_t")
          .add("odometry_channel", &S::odometry_channel, "", Range::nonEmpty(),
               "odometry_t: the wheels' actual velocities and the body velocity, every cycle");
  return table;
}

/// A drive watchdog time must outlast `period_ms`, the period of what it watches, or it would trip while
/// everything is healthy.
void checkWatchdog(const common::ConfigNode& node, const std::string& key, int value, int period_ms,
                   const std::string& period_name)
{
  if (value != 0 && value <= period_ms) {
    node.fail(key, std::to_string(value) + " ms is not longer than " + period_name + " (" +
                       std::to_string(period_ms) + " ms): the drive would stop a healthy driver");
  }
}

constexpr std::int64_t kMicrosecondsPerMillisecond = 1000;

}  // namespace

const common::ParameterTable<MotorSection>& motorParameters()
{
  static const auto table = makeMotorParameters();
  return table;
}

MotorConfig loadMotorSection(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("motor");
  MotorSection section;
  motorParameters().read(node, section);
  if (section.left_node_id == section.right_node_id) {
    node.fail("right_node_id", "equals left_node_id; each wheel drive needs its own node id");
  }
  if (section.master_node_id == section.left_node_id || section.master_node_id == section.right_node_id) {
    node.fail("master_node_id", "equals a drive's node id; the driver's heartbeat needs an id of its own");
  }
  checkWatchdog(node, "drive_watchdog.heartbeat_timeout_ms", section.drive_heartbeat_timeout_ms,
                section.master_heartbeat_ms, "master_heartbeat_ms");
  checkWatchdog(node, "drive_watchdog.rpdo_timeout_ms", section.drive_rpdo_timeout_ms, section.cycle_ms,
                "cycle_ms");
  MotorConfig config;
  MotorClientSettings client;
  client.heartbeat_timeout_us = section.heartbeat_timeout_ms * kMicrosecondsPerMillisecond;
  client.command_timeout_us = section.command_timeout_ms * kMicrosecondsPerMillisecond;
  client.stop_timeout_us = section.stop_timeout_ms * kMicrosecondsPerMillisecond;
  client.sdo_timeout_us = section.sdo_timeout_ms * kMicrosecondsPerMillisecond;
  client.sdo_attempts = section.sdo_attempts;
  config.drive.left = client;
  config.drive.right = client;
  config.drive.left.node_id = static_cast<std::uint8_t>(section.left_node_id);
  config.drive.right.node_id = static_cast<std::uint8_t>(section.right_node_id);
  config.master_node_id = static_cast<std::uint8_t>(section.master_node_id);
  config.master_heartbeat_period_us = section.master_heartbeat_ms * kMicrosecondsPerMillisecond;
  config.cycle_us = section.cycle_ms * kMicrosecondsPerMillisecond;
  config.command_future_tolerance_us = section.command_future_ms * kMicrosecondsPerMillisecond;
  config.drive_heartbeat_timeout_ms = static_cast<std::uint16_t>(section.drive_heartbeat_timeout_ms);
  config.drive_rpdo_timeout_ms = static_cast<std::uint16_t>(section.drive_rpdo_timeout_ms);
  config.status_channel = section.status_channel;
  config.odometry_channel = section.odometry_channel;
  config.odometry_timeout_us = section.odometry_timeout_ms * kMicrosecondsPerMillisecond;
  return config;
}

MotorConfig loadMotorConfig(const common::ConfigNode& root, const common::VehicleSettings& vehicle)
{
  MotorConfig config = loadMotorSection(root);
  config.drive.wheel_track_m = vehicle.wheel_track_m;
  config.drive.wheel_radius_m = vehicle.wheel_radius_m;
  return config;
}

MotorSection readMotorSection(const common::ConfigNode& root)
{
  MotorSection section;
  motorParameters().read(root.child("motor"), section);
  return section;
}

}  // namespace ifar::motor
