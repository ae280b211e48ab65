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

}  // namespace

MotorConfig loadMotorSection(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("motor");
  MotorConfig config;
  MotorClientSettings client;
  client.heartbeat_timeout_us = positiveMilliseconds(node, "heartbeat_timeout_ms", 300);
  client.command_timeout_us = positiveMilliseconds(node, "command_timeout_ms", 200);
  client.stop_timeout_us = positiveMilliseconds(node, "stop_timeout_ms", 1000);
  config.drive.left = client;
  config.drive.right = client;
  config.drive.left.node_id = nodeId(node, "left_node_id");
  config.drive.right.node_id = nodeId(node, "right_node_id");
  if (config.drive.left.node_id == config.drive.right.node_id) {
    node.fail("right_node_id", "equals left_node_id; each wheel drive needs its own node id");
  }
  config.cycle_us = positiveMilliseconds(node, "cycle_ms", 10);
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
