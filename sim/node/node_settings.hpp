#pragma once
// What config/sim.yaml holds for the simulator node (the daemon ifar-sim and the headless runner). The CAN
// `bus:` section has the same keys as config/can.yaml and is read by the daemon with can::loadBusSettings.

#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "sim/can_nodes/vehicle_can_nodes.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::sim {

enum class CommandSource { kCan, kLcm };

struct SimNodeSettings {
  std::string vehicle_config = "config/vehicle.yaml";
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
  CanNodeSettings can_nodes;
};

/// Reads the daemon's keys from the root of sim.yaml (all optional with the defaults above, except that
/// values present must be valid). Throws common::ConfigError naming the key. Leaves `bus` unread.
SimNodeSettings loadSimNodeSettings(const common::ConfigNode& root);

}  // namespace ifar::sim
