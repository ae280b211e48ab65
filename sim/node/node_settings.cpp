#include "sim/node/node_settings.hpp"

namespace ifar::sim {
namespace {

double nonNegative(const common::ConfigNode& node, const std::string& key, double fallback)
{
  const double value = node.optional<double>(key, fallback);
  if (!(value >= 0.0)) {
    node.fail(key, "must be zero or positive");
  }
  return value;
}

}  // namespace

SimNodeSettings loadSimNodeSettings(const common::ConfigNode& root)
{
  SimNodeSettings settings;
  settings.vehicle_config = root.optional<std::string>("vehicle_config", settings.vehicle_config);
  settings.world = root.optional<std::string>("world", settings.world);
  const auto seed = root.optional<std::int64_t>("seed", 1);
  if (seed < 0) {
    root.fail("seed", "must be zero or positive");
  }
  settings.simulator.seed = static_cast<std::uint64_t>(seed);

  if (root.has("physics")) {
    const auto physics = root.child("physics");
    settings.simulator.physics.step_seconds = 1.0 / physics.optionalPositive("step_hz", 200.0);
    settings.simulator.physics.surface_friction = physics.optionalPositive("surface_friction", 0.5);
    settings.simulator.physics.bumper_depth_m = physics.optionalPositive("bumper_depth_m", 0.05);
  }
  if (root.has("lidar")) {
    const auto lidar = root.child("lidar");
    settings.simulator.lidar_enabled = lidar.optional<bool>("enabled", true);
    settings.lidar_host = lidar.optional<std::string>("host", settings.lidar_host);
    const int port = lidar.optional<int>("port", settings.lidar_port);
    if (port < 1 || port > 65535) {
      lidar.fail("port", "must be a UDP port, 1..65535");
    }
    settings.lidar_port = static_cast<std::uint16_t>(port);
    settings.simulator.lidar_rotation_hz = lidar.optionalPositive("rotation_hz", 10.0);
    settings.simulator.lidar_max_range_m = lidar.optionalPositive("max_range_m", 100.0);
    settings.simulator.lidar_scene.cell_size_m = lidar.optionalPositive("grid_cell_m", 2.0);
  }
  if (root.has("pose")) {
    const auto pose = root.child("pose");
    settings.pose_channel = pose.optional<std::string>("channel", settings.pose_channel);
    settings.pose_rate_hz = pose.optionalPositive("rate_hz", settings.pose_rate_hz);
    settings.simulator.pose_noise_position_m = nonNegative(pose, "noise_position_m", 0.0);
    settings.simulator.pose_noise_heading_rad = nonNegative(pose, "noise_heading_rad", 0.0);
  }
  if (root.has("ground_truth")) {
    const auto truth = root.child("ground_truth");
    settings.ground_truth_channel = truth.optional<std::string>("channel", settings.ground_truth_channel);
    settings.ground_truth_rate_hz = truth.optionalPositive("rate_hz", settings.ground_truth_rate_hz);
  }
  if (root.has("commands")) {
    const auto commands = root.child("commands");
    const auto source = commands.optional<std::string>("source", "can");
    if (source == "can") {
      settings.command_source = CommandSource::kCan;
    } else if (source == "lcm") {
      settings.command_source = CommandSource::kLcm;
    } else {
      commands.fail("source", "must be 'can' (RPDO frames to the emulated drives) or 'lcm' (velocity_cmd_t)");
    }
    settings.velocity_channel = commands.optional<std::string>("velocity_channel", settings.velocity_channel);
    settings.command_timeout_s = commands.optionalPositive("timeout_s", settings.command_timeout_s);
  }
  if (root.has("can_nodes")) {
    const auto nodes = root.child("can_nodes");
    auto nodeId = [&](const std::string& key, int fallback) {
      const int id = nodes.optional<int>(key, fallback);
      if (id < 1 || id > 127) {
        nodes.fail(key, "must be a CANopen node id, 1..127");
      }
      return static_cast<std::uint8_t>(id);
    };
    settings.can_nodes.left_node_id = nodeId("left_node_id", 1);
    settings.can_nodes.right_node_id = nodeId("right_node_id", 2);
    if (settings.can_nodes.left_node_id == settings.can_nodes.right_node_id) {
      nodes.fail("right_node_id", "must differ from left_node_id");
    }
    const int frame_id =
        nodes.optional<int>("force_frame_id", static_cast<int>(force_sensor::kDefaultFrameId));
    if (frame_id < 0 || frame_id > 0x7FF) {
      nodes.fail("force_frame_id", "must be a standard id, 0..2047 (0x7FF)");
    }
    settings.can_nodes.force_frame_id = static_cast<std::uint32_t>(frame_id);
  }
  return settings;
}

}  // namespace ifar::sim
