#pragma once
// The `motor` section of config/can.yaml as DifferentialDrive settings, for the executive (library
// ifar_motor_config; ifar_motor itself stays free of the YAML stack).
//
//   motor:
//     left_node_id: 1
//     right_node_id: 2
//     cycle_ms: 10
//     heartbeat_timeout_ms: 300
//     command_timeout_ms: 200
//     stop_timeout_ms: 1000
//     status_channel: MOTOR_STATUS

#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "common/vehicle.hpp"
#include "drivers/motor/differential_drive.hpp"

namespace ifar::motor {

struct MotorConfig {
  DifferentialDriveSettings drive;
  std::int64_t cycle_us = 10'000;
  std::string status_channel = "MOTOR_STATUS";
};

/// Reads root.motor alone, without the wheel geometry. Throws as loadMotorConfig does; ifar-force-driver
/// checks the motor section of the shared can.yaml with it, so a bad file stops both daemons alike.
MotorConfig loadMotorSection(const common::ConfigNode& root);

/// Reads root.motor; wheel geometry comes from the vehicle. Throws common::ConfigError naming the key
/// for node ids outside 1..127, equal node ids, or non-positive periods.
MotorConfig loadMotorConfig(const common::ConfigNode& root, const common::VehicleSettings& vehicle);

}  // namespace ifar::motor
