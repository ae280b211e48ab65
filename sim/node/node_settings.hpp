#pragma once
// What config/sim.yaml holds for the simulator node (the daemon ifar-sim and the headless runner). The CAN
// bus, the drives' node ids and the force sensor's frame id are the vehicle's CAN configuration: the
// simulator reads them from can.yaml (sim.yaml `can_config`), the file the CAN drivers read.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "sim/can_nodes/vehicle_can_nodes.hpp"
#include "sim/sensing/sensing_settings.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::sim {

enum class CommandSource { kCan, kLcm };

struct SimNodeSettings {
  std::string vehicle_config = "vehicle.yaml";  // relative: beside sim.yaml, else on the search path
  std::string can_config = "can.yaml";
  std::string world;  // world file used when none is given on the command line
  SimulatorSettings simulator;
  std::string lidar_host = "127.0.0.1";
  std::uint16_t lidar_port = 2368;
  std::string pose_channel = "POSE";
  double pose_rate_hz = 50.0;
  std::string ground_truth_channel = "SIM_GROUND_TRUTH";
  double ground_truth_rate_hz = 20.0;
  CommandSource command_source = CommandSource::kCan;
  std::string velocity_channel = "VELOCITY_CMD";
  double command_timeout_s = 0.5;  // an LCM velocity command older than this counts as zero
  CanNodeSettings can_nodes;       // from can.yaml (loadCanNodes), not sim.yaml
};

/// sim.yaml's keys, every one optional.
const common::ParameterTable<SimNodeSettings>& simNodeParameters();

/// Reads the daemon's keys from the root of sim.yaml (all optional with the defaults above, except that
/// values present must be valid). Throws common::ConfigError naming the key. Leaves the unknown-key
/// check to the caller. The sensing models start from `sensing.profile`'s values (sensingProfile) and
/// every other `sensing.` key present overrides one of them.
SimNodeSettings loadSimNodeSettings(const common::ConfigNode& root);
/// The same with the profile given (a command line's --sensing) instead of the file's `sensing.profile`;
/// the file's other sensing keys still override its values. std::nullopt = the file's profile.
SimNodeSettings loadSimNodeSettings(const common::ConfigNode& root, std::optional<SensingProfile> profile);
/// The profile named `name` ("ideal", "field"); throws std::invalid_argument naming the known ones.
SensingProfile parseSensingProfile(std::string_view name);

/// The emulated drives' node ids and the force sensor's frame id from can.yaml (`can_root`), checked by
/// the CAN drivers' own loaders; the rest of `nodes` is kept.
CanNodeSettings loadCanNodes(const common::ConfigNode& can_root, CanNodeSettings nodes = {});

}  // namespace ifar::sim
