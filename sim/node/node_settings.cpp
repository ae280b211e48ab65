#include "sim/node/node_settings.hpp"

#include "drivers/force_sensor/force_sensor_config.hpp"
#include "drivers/motor/motor_config.hpp"

namespace ifar::sim {
namespace {

using Range = common::ParameterRange;
using Table = common::ParameterTable<SimNodeSettings>;

void addSimulator(Table& table)
{
  table
      .converted<double>(
          "physics.step_hz", "Hz", Range::positive(), "fixed Box2D steps per simulated second",
          [](const SimNodeSettings& s) { return 1.0 / s.simulator.physics.step_seconds; },
          [](SimNodeSettings& s, double rate) { s.simulator.physics.step_seconds = 1.0 / rate; })
      .add(
          "physics.surface_friction", [](auto& s) -> auto& { return s.simulator.physics.surface_friction; },
          "", Range::positive(), "object-object and object-wall Coulomb coefficient")
      .add(
          "physics.bumper_depth_m", [](auto& s) -> auto& { return s.simulator.physics.bumper_depth_m; }, "m",
          Range::positive(), "thickness of the bumper plate")
      .add(
          "lidar.enabled", [](auto& s) -> auto& { return s.simulator.lidar_enabled; }, "", Range::any(),
          "the simulated VLP-16 sends packets")
      .add("lidar.host", &SimNodeSettings::lidar_host, "", Range::nonEmpty(),
           "where the VLP-16 data packets go (the velodyne driver's address)")
      .add("lidar.port", &SimNodeSettings::lidar_port, "", Range::between(1, 65535),
           "UDP port of the data packets (the driver's data_port)")
      .add(
          "lidar.rotation_hz", [](auto& s) -> auto& { return s.simulator.lidar_rotation_hz; }, "Hz",
          Range::positive(), "VLP-16 revolutions per second")
      .add(
          "lidar.max_range_m", [](auto& s) -> auto& { return s.simulator.lidar_max_range_m; }, "m",
          Range::positive(), "the VLP-16's range: farther surfaces give no return")
      .add(
          "lidar.grid_cell_m", [](auto& s) -> auto& { return s.simulator.lidar_scene.cell_size_m; }, "m",
          Range::positive(), "ray-casting grid cell")
      .add(
          "pose.noise_position_m", [](auto& s) -> auto& { return s.simulator.pose_noise_position_m; }, "m",
          Range::nonNegative(), "standard deviation of the Gaussian noise on the reported x and y")
      .add(
          "pose.noise_heading_rad", [](auto& s) -> auto& { return s.simulator.pose_noise_heading_rad; },
          "rad", Range::nonNegative(), "standard deviation of the noise on the reported heading");
}

Table makeSimNodeParameters()
{
  using S = SimNodeSettings;
  Table table;
  table
      .add("vehicle_config", &S::vehicle_config, "", Range::nonEmpty(),
           "dimensions, limits, lidar mount, force sensor range (relative to the working directory)")
      .add("can_config", &S::can_config, "", Range::nonEmpty(),
           "the vehicle's CAN bus, drive node ids and force frame id: the file the CAN drivers read")
      .add("world", &S::world, "", Range::any(), "world file used when none is given on the command line")
      .add(
          "seed", [](auto& s) -> auto& { return s.simulator.seed; }, "", Range::nonNegative(),
          "pose noise (and anything else random) is seeded: same seed, same run");
  addSimulator(table);
  table.add("pose.channel", &S::pose_channel, "", Range::nonEmpty(), "where the pose estimate goes (pose_t)")
      .add("pose.rate_hz", &S::pose_rate_hz, "Hz", Range::positive(), "pose estimates per second")
      .add("ground_truth.channel", &S::ground_truth_channel, "", Range::nonEmpty(),
           "evaluation only: never read by planner or executive")
      .add("ground_truth.rate_hz", &S::ground_truth_rate_hz, "Hz", Range::positive(),
           "ground truth per second")
      .choice("commands.source", &S::command_source,
              {{"can", CommandSource::kCan}, {"lcm", CommandSource::kLcm}},
              "can: RPDO1 frames to the emulated drives; lcm: velocity_cmd_t on commands.velocity_channel")
      .add("commands.velocity_channel", &S::velocity_channel, "", Range::nonEmpty(),
           "lcm source: velocity commands (velocity_cmd_t)")
      .add("commands.timeout_s", &S::command_timeout_s, "s", Range::positive(),
           "lcm source: an older command counts as zero");
  return table;
}

}  // namespace

const common::ParameterTable<SimNodeSettings>& simNodeParameters()
{
  static const Table table = makeSimNodeParameters();
  return table;
}

SimNodeSettings loadSimNodeSettings(const common::ConfigNode& root)
{
  SimNodeSettings settings;
  simNodeParameters().read(root, settings);
  return settings;
}

CanNodeSettings loadCanNodes(const common::ConfigNode& can_root, CanNodeSettings nodes)
{
  const motor::MotorConfig motor = motor::loadMotorSection(can_root);
  nodes.left_node_id = motor.drive.left.node_id;
  nodes.right_node_id = motor.drive.right.node_id;
  nodes.force_frame_id = force_sensor::loadForceSensorConfig(can_root).monitor.frame_id;
  return nodes;
}

}  // namespace ifar::sim
