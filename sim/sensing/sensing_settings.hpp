#pragma once
// How the simulated sensors differ from the truth: the parameters of each sensing model and the two
// profiles they start from. `ideal` is exact (the simulator as it always was: every model off);
// `field` is what a field vehicle's sensors give (docs/simulator.md, "Sensing models", gives each
// default's source). sim.yaml `sensing.profile` picks a profile and any key under `sensing:`
// overrides one of its values.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ifar::sim {

enum class SensingProfile { kIdeal, kField };

/// The pose as a state estimator publishes it: the truth with a drift that grows with distance and
/// turning (a random walk, integrated through the vehicle's motion like dead reckoning), jitter, latency
/// and occasional corrections back toward the truth.
struct PoseModelSettings {
  double jitter_position_m = 0.0;               // sigma of the white noise on each published x and y
  double jitter_heading_rad = 0.0;              // sigma of the white noise on each published heading
  double drift_position_m_per_sqrt_m = 0.0;     // position random walk along and across the motion
  double drift_heading_rad_per_sqrt_m = 0.0;    // heading random walk per distance travelled
  double drift_heading_rad_per_sqrt_rad = 0.0;  // heading random walk per angle turned
  double latency_s = 0.0;                       // the published pose is the estimate of this long ago
  double correction_interval_s = 0.0;           // mean time between corrections (Poisson); 0 = never
  double correction_fraction = 0.0;             // share of the drift a correction removes, 0..1

  bool drifts() const
  {
    return drift_position_m_per_sqrt_m > 0.0 || drift_heading_rad_per_sqrt_m > 0.0 ||
           drift_heading_rad_per_sqrt_rad > 0.0;
  }
};

/// The VLP-16's returns: range noise, random dropouts, no return from a surface too dark or too oblique
/// for its range, calibrated-reflectivity noise, false retro-reflector readings on diffuse surfaces and
/// missed ones on retro-reflective tags.
struct LidarModelSettings {
  double range_noise_m = 0.0;  // sigma of the Gaussian noise on each slant range
  double dropout_rate = 0.0;   // share of returns lost at random, 0..1
  /// Farthest return from a 10 %-reflective surface met head-on; the reach of any surface scales with
  /// sqrt(reflectivity x cos(incidence) / 0.1) (received power ~ reflectivity cos(incidence) / r^2).
  /// 0 = every surface within max_range_m returns.
  double detection_range_m = 0.0;
  double reflectivity_noise = 0.0;   // sigma of the noise on the calibrated reflectivity (0..255 units)
  double false_tag_rate = 0.0;       // share of diffuse wall and top returns read as retro-reflective
  double missed_tag_rate = 0.0;      // share of retro-reflective returns read as diffuse
  int retro_threshold = 101;         // VLP-16 calibrated reflectivity: 0..100 diffuse, 101..255 retro
  int false_tag_reflectivity = 150;  // what a false tag reads (a specular glint)
  int missed_tag_reflectivity = 60;  // what a missed tag reads (the diffuse board behind it)

  bool active() const
  {
    return range_noise_m > 0.0 || dropout_rate > 0.0 || detection_range_m > 0.0 || reflectivity_noise > 0.0 ||
           false_tag_rate > 0.0 || missed_tag_rate > 0.0;
  }
};

/// The wheels: tyre slip that grows with the traction the tyre transmits, and the drives' velocity
/// measured by counting encoder edges.
struct WheelModelSettings {
  /// Tyre force F = traction limit x (1 - exp(-slip ratio / slip_ratio_scale)): the slip ratio at which
  /// a wheel transmits 63 % of its traction limit. 0 = a rigid tyre (the speed controller's own slip).
  double slip_ratio_scale = 0.0;
  int encoder_counts_per_rev = 0;   // edges per wheel revolution; 0 = the exact wheel speed
  double velocity_window_s = 0.01;  // the drive counts edges over this window for its velocity
};

/// The bumper force sensor: noise, a slowly drifting zero, hung-firmware episodes (the CAN controller
/// repeats the last frame: value and counter stuck) and lost frames.
struct ForceModelSettings {
  double noise_n = 0.0;           // sigma of the white noise on each reading
  double bias_sigma_n = 0.0;      // steady-state sigma of the zero drift (first-order Gauss-Markov)
  double bias_time_s = 60.0;      // correlation time of the zero drift
  double stuck_interval_s = 0.0;  // mean time between stuck episodes (Poisson); 0 = never
  double stuck_duration_s = 0.1;  // how long an episode repeats the same frame
  double drop_rate = 0.0;         // share of frames lost, 0..1
};

struct SensingSettings {
  SensingProfile profile = SensingProfile::kIdeal;  // the profile the values started from
  PoseModelSettings pose;
  LidarModelSettings lidar;
  WheelModelSettings wheels;
  ForceModelSettings force;

  /// False when no model draws from the seed (the ideal profile): every seed then gives the same run.
  bool drawsRandomNumbers() const
  {
    return pose.jitter_position_m > 0.0 || pose.jitter_heading_rad > 0.0 || pose.drifts() ||
           pose.correction_interval_s > 0.0 || lidar.active() || force.noise_n > 0.0 ||
           force.bias_sigma_n > 0.0 || force.stuck_interval_s > 0.0 || force.drop_rate > 0.0;
  }
};

/// The profile's values.
SensingSettings sensingProfile(SensingProfile profile);
/// The profile named `name` ("ideal", "field"); throws std::invalid_argument naming the known profiles.
SensingSettings sensingProfile(std::string_view name);
const char* sensingProfileName(SensingProfile profile);
std::vector<std::string> sensingProfileNames();

/// Independent random streams from one seed: each sensor model draws from its own, so turning one
/// model on or off leaves the others' sequences unchanged.
std::uint64_t sensingStreamSeed(std::uint64_t seed, std::uint64_t stream);
constexpr std::uint64_t kPoseDriftStream = 1;
constexpr std::uint64_t kLidarStream = 2;
constexpr std::uint64_t kForceStream = 3;

}  // namespace ifar::sim
