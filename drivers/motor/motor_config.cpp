#include "drivers/motor/motor_config.hpp"

namespace ifar::motor {
namespace {

std::int64_t positiveMilliseconds(const common::ConfigNode& node, const std::string& key, int fallback)
{
  const int value = node.optional<int>(key, fallback);
  if (value <= 0) {
    node.fail(key, "must be a positive number of milliseconds, got " + std::to_string(value));
  }
  return static_cast<std::int64_t>(value) * 1000;
}

std::uint8_t nodeId(const common::ConfigNode& node, const std::string& key)
{
  const int value = node.required<int>(key);
  if (value < 1 || value > 127) {
    node.fail(key, "CANopen node id must be 1..127, got " + std::to_string(value));
  }
  return static_cast<std::uint8_t>(value);
}

/// A drive watchdog time (16-bit milliseconds in the drive, 0 = off) that must outlast `period_us`, the
/// period of what it watches, or it would trip while everything is healthy.
std::uint16_t watchdogMilliseconds(const common::ConfigNode& node, const std::string& key, int fallback,
                                   std::int64_t period_us, const std::string& period_name)
{
  const int value = node.optional<int>(key, fallback);
  if (value < 0 || value > 65535) {
    node.fail(key, "must be 0 (off) or 1..65535 milliseconds, got " + std::to_string(value));
  }
  if (value != 0 && static_cast<std::int64_t>(value) * 1000 <= period_us) {
    node.fail(key, std::to_string(value) + " ms is not longer than " + period_name + " (" +
                       std::to_string(period_us / 1000) + " ms): the drive would stop a healthy driver");
  }
  return static_cast<std::uint16_t>(value);
}

void readDriveWatchdog(const common::ConfigNode& node, MotorConfig& config)
{
  if (!node.has("drive_watchdog")) {
    return;
  }
  const common::ConfigNode watchdog = node.child("drive_watchdog");
  config.drive_heartbeat_timeout_ms =
      watchdogMilliseconds(watchdog, "heartbeat_timeout_ms", config.drive_heartbeat_timeout_ms,
                           config.master_heartbeat_period_us, "master_heartbeat_ms");
  config.drive_rpdo_timeout_ms = watchdogMilliseconds(
      watchdog, "rpdo_timeout_ms", config.drive_rpdo_timeout_ms, config.cycle_us, "cycle_ms");
}

MotorClientSettings clientSettings(const common::ConfigNode& node)
{
  MotorClientSettings client;
  client.heartbeat_timeout_us = positiveMilliseconds(node, "heartbeat_timeout_ms", 300);
  client.command_timeout_us = positiveMilliseconds(node, "command_timeout_ms", 150);
  client.stop_timeout_us = positiveMilliseconds(node, "stop_timeout_ms", 1000);
  client.sdo_timeout_us = positiveMilliseconds(node, "sdo_timeout_ms", 50);
  client.sdo_attempts = node.optional<int>("sdo_attempts", 3);
  if (client.sdo_attempts < 1 || client.sdo_attempts > 100) {
    node.fail("sdo_attempts", "must be 1..100, got " + std::to_string(client.sdo_attempts));
  }
  return client;
}

}  // namespace

MotorConfig loadMotorSection(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("motor");
  MotorConfig config;
  const MotorClientSettings client = clientSettings(node);
  config.drive.left = client;
  config.drive.right = client;
  config.drive.left.node_id = nodeId(node, "left_node_id");
  config.drive.right.node_id = nodeId(node, "right_node_id");
  if (config.drive.left.node_id == config.drive.right.node_id) {
    node.fail("right_node_id", "equals left_node_id; each wheel drive needs its own node id");
  }
  if (node.has("master_node_id")) {
    config.master_node_id = nodeId(node, "master_node_id");
  }
  if (config.master_node_id == config.drive.left.node_id ||
      config.master_node_id == config.drive.right.node_id) {
    node.fail("master_node_id", "equals a drive's node id; the driver's heartbeat needs an id of its own");
  }
  config.master_heartbeat_period_us = positiveMilliseconds(node, "master_heartbeat_ms", 50);
  config.cycle_us = positiveMilliseconds(node, "cycle_ms", 10);
  config.command_future_tolerance_us = positiveMilliseconds(node, "command_future_ms", 50);
  readDriveWatchdog(node, config);
  config.status_channel = node.optional<std::string>("status_channel", config.status_channel);
  return config;
}

MotorConfig loadMotorConfig(const common::ConfigNode& root, const common::VehicleSettings& vehicle)
{
  MotorConfig config = loadMotorSection(root);
  config.drive.wheel_track_m = vehicle.wheel_track_m;
  config.drive.wheel_radius_m = vehicle.wheel_radius_m;
  return config;
}

}  // namespace ifar::motor
