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
          "pose.noise_position_m",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.jitter_position_m; }, "m",
          Range::nonNegative(),
          "older name of sensing.pose.jitter_position_m (read after it when both are given)")
      .add(
          "pose.noise_heading_rad",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.jitter_heading_rad; }, "rad",
          Range::nonNegative(),
          "older name of sensing.pose.jitter_heading_rad (read after it when both are given)");
}

/// Every sensing model's parameters under `sensing:`; their defaults are the profile's (the reference
/// shows the ideal profile's).
void addSensing(Table& table)
{
  const auto fraction = Range::between(0.0, 1.0);
  const auto reflectivity = Range::between(0, 255);
  table
      .choice(
          "sensing.profile", [](auto& s) -> auto& { return s.simulator.sensing.profile; },
          {{"ideal", SensingProfile::kIdeal}, {"field", SensingProfile::kField}},
          "ideal: every sensor exact; field: a field vehicle's estimator, lidar, wheels and force sensor "
          "(docs/simulator.md); the keys below override its values")
      .add(
          "sensing.pose.jitter_position_m",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.jitter_position_m; }, "m",
          Range::nonNegative(), "sigma of the white noise on each published x and y (field 0.01)")
      .add(
          "sensing.pose.jitter_heading_rad",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.jitter_heading_rad; }, "rad",
          Range::nonNegative(), "sigma of the white noise on each published heading (field 0.002)")
      .add(
          "sensing.pose.drift_position_m_per_sqrt_m",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.drift_position_m_per_sqrt_m; }, "m/sqrt(m)",
          Range::nonNegative(),
          "position random walk along and across the motion: sigma after d metres is this x sqrt(d) (field "
          "0.0316: 10 cm after 10 m)")
      .add(
          "sensing.pose.drift_heading_rad_per_sqrt_m",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.drift_heading_rad_per_sqrt_m; },
          "rad/sqrt(m)", Range::nonNegative(),
          "heading random walk per distance travelled (field 0.00276: 0.5 degree after 10 m)")
      .add(
          "sensing.pose.drift_heading_rad_per_sqrt_rad",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.drift_heading_rad_per_sqrt_rad; },
          "rad/sqrt(rad)", Range::nonNegative(),
          "heading random walk per angle turned (field 0.002: 0.3 degree after a full turn)")
      .add(
          "sensing.pose.latency_s", [](auto& s) -> auto& { return s.simulator.sensing.pose.latency_s; }, "s",
          Range::between(0.0, 1.0),
          "the published pose is the estimate of this long ago, stamped so (field 0.05)")
      .add(
          "sensing.pose.correction_interval_s",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.correction_interval_s; }, "s",
          Range::nonNegative(),
          "mean time between corrections toward the truth (loop closure, GNSS fix; Poisson); 0 = never "
          "(field 20)")
      .add(
          "sensing.pose.correction_fraction",
          [](auto& s) -> auto& { return s.simulator.sensing.pose.correction_fraction; }, "", fraction,
          "share of the drift a correction removes at once (field 0.8)")
      .add(
          "sensing.lidar.range_noise_m",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.range_noise_m; }, "m", Range::nonNegative(),
          "sigma of the Gaussian noise on each range (field 0.015: the VLP-16's +-3 cm as 2 sigma)")
      .add(
          "sensing.lidar.dropout_rate",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.dropout_rate; }, "", fraction,
          "share of returns lost at random (field 0.01)")
      .add(
          "sensing.lidar.detection_range_m",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.detection_range_m; }, "m",
          Range::nonNegative(),
          "farthest return from a 10 % surface head-on; reach scales with sqrt(reflectivity x cos(incidence) "
          "/ 0.1), "
          "so dark and grazing surfaces vanish first; 0 = all within max_range_m (field 50)")
      .add(
          "sensing.lidar.reflectivity_noise",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.reflectivity_noise; }, "",
          Range::nonNegative(), "sigma of the noise on the calibrated reflectivity, 0..255 units (field 3)")
      .add(
          "sensing.lidar.false_tag_rate",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.false_tag_rate; }, "", fraction,
          "share of diffuse wall and top returns read as a retro-reflective tag (field 0.0002)")
      .add(
          "sensing.lidar.missed_tag_rate",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.missed_tag_rate; }, "", fraction,
          "share of retro-reflective (tag) returns read as diffuse (field 0.05)")
      .add(
          "sensing.lidar.retro_threshold",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.retro_threshold; }, "", reflectivity,
          "calibrated reflectivity from which a surface is retro-reflective (VLP-16: 101..255)")
      .add(
          "sensing.lidar.false_tag_reflectivity",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.false_tag_reflectivity; }, "", reflectivity,
          "what a false tag return reads")
      .add(
          "sensing.lidar.missed_tag_reflectivity",
          [](auto& s) -> auto& { return s.simulator.sensing.lidar.missed_tag_reflectivity; }, "",
          reflectivity, "what a missed tag return reads")
      .add(
          "sensing.wheels.slip_ratio_scale",
          [](auto& s) -> auto& { return s.simulator.sensing.wheels.slip_ratio_scale; }, "",
          Range::nonNegative(),
          "tyre force = traction limit x (1 - exp(-slip ratio / this)): the slip ratio at 63 % of the limit; "
          "0 = rigid tyre (field 0.1)")
      .add(
          "sensing.wheels.encoder_counts_per_rev",
          [](auto& s) -> auto& { return s.simulator.sensing.wheels.encoder_counts_per_rev; }, "",
          Range::nonNegative(),
          "encoder edges per wheel revolution behind the drives' actual velocity; 0 = exact (field 4096)")
      .add(
          "sensing.wheels.velocity_window_s",
          [](auto& s) -> auto& { return s.simulator.sensing.wheels.velocity_window_s; }, "s",
          Range::positive(), "the drive counts edges over this window for its actual velocity (field 0.01)")
      .add(
          "sensing.force.noise_n", [](auto& s) -> auto& { return s.simulator.sensing.force.noise_n; }, "N",
          Range::nonNegative(), "sigma of the white noise on each force reading (field 2)")
      .add(
          "sensing.force.bias_sigma_n",
          [](auto& s) -> auto& { return s.simulator.sensing.force.bias_sigma_n; }, "N", Range::nonNegative(),
          "steady sigma of the wandering zero (first-order Gauss-Markov, tared to 0 at start; field 3)")
      .add(
          "sensing.force.bias_time_s", [](auto& s) -> auto& { return s.simulator.sensing.force.bias_time_s; },
          "s", Range::positive(), "correlation time of the wandering zero (field 60)")
      .add(
          "sensing.force.stuck_interval_s",
          [](auto& s) -> auto& { return s.simulator.sensing.force.stuck_interval_s; }, "s",
          Range::nonNegative(),
          "mean time between episodes of a repeated frame (value and counter stuck; Poisson); 0 = never "
          "(field 60)")
      .add(
          "sensing.force.stuck_duration_s",
          [](auto& s) -> auto& { return s.simulator.sensing.force.stuck_duration_s; }, "s", Range::positive(),
          "how long such an episode lasts (field 0.1)")
      .add(
          "sensing.force.drop_rate", [](auto& s) -> auto& { return s.simulator.sensing.force.drop_rate; }, "",
          fraction, "share of force frames lost (field 0.005)");
}

Table makeSimNodeParameters()
{
  using S = SimNodeSettings;
  Table table;
  table
      .add(
          "vehicle_config", &S::vehicle_config, "", Range::nonEmpty(),
          "dimensions, limits, lidar mount, force sensor range (a relative path is beside this file, else on "
          "the configuration search path)")
      .add(
          "can_config", &S::can_config, "", Range::nonEmpty(),
          "the vehicle's CAN bus, drive node ids and force frame id: the file the CAN drivers read (relative "
          "as vehicle_config)")
      .add("world", &S::world, "", Range::any(),
           "world file (or a name in worlds/ on the configuration search path) used when none is given on "
           "the command line")
      .add(
          "seed", [](auto& s) -> auto& { return s.simulator.seed; }, "", Range::nonNegative(),
          "every sensing model (and anything else random) is seeded: same seed, same run");
  addSensing(table);
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
  return loadSimNodeSettings(root, std::nullopt);
}

SimNodeSettings loadSimNodeSettings(const common::ConfigNode& root, std::optional<SensingProfile> profile)
{
  SimNodeSettings settings;
  if (!profile) {
    // The profile first: its values are the defaults the other sensing keys override.
    static const auto profile_only = common::ParameterTable<SimNodeSettings>().choice(
        "sensing.profile", [](auto& s) -> auto& { return s.simulator.sensing.profile; },
        {{"ideal", SensingProfile::kIdeal}, {"field", SensingProfile::kField}}, "");
    profile_only.read(root, settings);
  }
  settings.simulator.sensing = sensingProfile(profile.value_or(settings.simulator.sensing.profile));
  simNodeParameters().read(root, settings);
  if (profile) {
    settings.simulator.sensing.profile = *profile;
  }
  return settings;
}

SensingProfile parseSensingProfile(std::string_view name)
{
  return sensingProfile(name).profile;
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
