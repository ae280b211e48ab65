#include "sim/sensing/sensing_settings.hpp"

#include <stdexcept>

namespace ifar::sim {
namespace {

/// A field vehicle's sensors (docs/simulator.md, "Sensing models": where each figure comes from).
SensingSettings fieldProfile()
{
  SensingSettings sensing;
  sensing.profile = SensingProfile::kField;
  auto& pose = sensing.pose;
  pose.jitter_position_m = 0.01;
  pose.jitter_heading_rad = 0.002;
  pose.drift_position_m_per_sqrt_m = 0.0316;    // 10 cm (1 %) after 10 m
  pose.drift_heading_rad_per_sqrt_m = 0.00276;  // 0.5 degree after 10 m
  pose.drift_heading_rad_per_sqrt_rad = 0.002;  // 0.3 degree after a full turn
  pose.latency_s = 0.05;
  pose.correction_interval_s = 20.0;
  pose.correction_fraction = 0.8;
  auto& lidar = sensing.lidar;
  lidar.range_noise_m = 0.015;  // the VLP-16's +-3 cm taken as two sigma
  lidar.dropout_rate = 0.01;
  lidar.detection_range_m = 50.0;
  lidar.reflectivity_noise = 3.0;
  lidar.false_tag_rate = 0.0002;
  lidar.missed_tag_rate = 0.05;
  auto& wheels = sensing.wheels;
  wheels.slip_ratio_scale = 0.1;
  wheels.encoder_counts_per_rev = 4096;
  wheels.velocity_window_s = 0.01;
  auto& force = sensing.force;
  force.noise_n = 2.0;
  force.bias_sigma_n = 3.0;
  force.bias_time_s = 60.0;
  force.stuck_interval_s = 60.0;
  force.stuck_duration_s = 0.1;
  force.drop_rate = 0.005;
  return sensing;
}

}  // namespace

SensingSettings sensingProfile(SensingProfile profile)
{
  return profile == SensingProfile::kField ? fieldProfile() : SensingSettings{};
}

SensingSettings sensingProfile(std::string_view name)
{
  for (const SensingProfile profile : {SensingProfile::kIdeal, SensingProfile::kField}) {
    if (name == sensingProfileName(profile)) {
      return sensingProfile(profile);
    }
  }
  throw std::invalid_argument("unknown sensing profile '" + std::string(name) + "' (ideal, field)");
}

const char* sensingProfileName(SensingProfile profile)
{
  return profile == SensingProfile::kField ? "field" : "ideal";
}

std::vector<std::string> sensingProfileNames()
{
  return {sensingProfileName(SensingProfile::kIdeal), sensingProfileName(SensingProfile::kField)};
}

std::uint64_t sensingStreamSeed(std::uint64_t seed, std::uint64_t stream)
{
  // splitmix64 of the seed offset by the stream: nearby seeds and streams give unrelated states.
  std::uint64_t state = seed + stream * 0x9E3779B97F4A7C15ULL;
  state = (state ^ (state >> 30)) * 0xBF58476D1CE4E5B9ULL;
  state = (state ^ (state >> 27)) * 0x94D049BB133111EBULL;
  return state ^ (state >> 31);
}

}  // namespace ifar::sim
