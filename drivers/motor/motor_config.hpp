#pragma once
// The `motor` section of config/can.yaml as DifferentialDrive settings and the motor driver's own
// timing, for ifar-motor-driver (library ifar_motor_config; ifar_motor itself stays free of the YAML
// stack).
//
//   motor:
//     left_node_id: 1
//     right_node_id: 2
//     master_node_id: 127          # the driver's own node id: its heartbeat is 0x700 + 127
//     master_heartbeat_ms: 50
//     cycle_ms: 10
//     heartbeat_timeout_ms: 300
//     command_timeout_ms: 150
//     command_future_ms: 50
//     stop_timeout_ms: 1000
//     sdo_timeout_ms: 50
//     sdo_attempts: 3
//     drive_watchdog:
//       heartbeat_timeout_ms: 150
//       rpdo_timeout_ms: 100
//     status_channel: MOTOR_STATUS
//     odometry_timeout_ms: 50
//     odometry_channel: ODOMETRY

#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "common/vehicle.hpp"
#include "drivers/motor/differential_drive.hpp"

namespace ifar::motor {

struct MotorConfig {
  DifferentialDriveSettings drive;
  std::int64_t cycle_us = 10'000;
  std::string status_channel = "MOTOR_STATUS";
  std::string odometry_channel = "ODOMETRY";         // odometry_t, every cycle
  std::int64_t odometry_timeout_us = 50'000;         // a drive without TPDO1 this long is stale in odometry_t
  std::uint8_t master_node_id = 127;                 // this driver's CANopen node id
  std::int64_t master_heartbeat_period_us = 50'000;  // the driver's heartbeat, 0x700 + master_node_id
  std::uint16_t drive_heartbeat_timeout_ms = 150;    // 0x1016 in each drive; 0 = not watched
  std::uint16_t drive_rpdo_timeout_ms = 100;         // 0x1400:05 in each drive; 0 = not watched
  std::int64_t command_future_tolerance_us = 50'000;  // a command stamped further ahead is refused
};

/// can.yaml `motor:` as the file writes it (node ids, milliseconds); loadMotorSection makes a MotorConfig
/// of it.
struct MotorSection {
  int left_node_id = 1;
  int right_node_id = 2;
  int master_node_id = 127;
  int master_heartbeat_ms = 50;
  int cycle_ms = 10;
  int heartbeat_timeout_ms = 300;
  int command_timeout_ms = 150;
  int command_future_ms = 50;
  int stop_timeout_ms = 1000;
  int sdo_timeout_ms = 50;
  int sdo_attempts = 3;
  int drive_heartbeat_timeout_ms = 150;
  int drive_rpdo_timeout_ms = 100;
  std::string status_channel = "MOTOR_STATUS";
  int odometry_timeout_ms = 50;
  std::string odometry_channel = "ODOMETRY";
};

/// can.yaml `motor:` keys: the node ids required, the rest optional.
const common::ParameterTable<MotorSection>& motorParameters();

/// root.motor's keys as written, unchecked beyond their ranges (for --print-config, after a load).
MotorSection readMotorSection(const common::ConfigNode& root);

/// Reads root.motor alone, without the wheel geometry. Throws as loadMotorConfig does; ifar-force-driver
/// checks the motor section of the shared can.yaml with it, so a bad file stops both daemons alike.
MotorConfig loadMotorSection(const common::ConfigNode& root);

/// Reads root.motor; wheel geometry comes from the vehicle. Throws common::ConfigError naming the key
/// for node ids outside 1..127, equal node ids, non-positive periods, or drive watchdog times that
/// cannot work (not longer than the period of what they watch).
MotorConfig loadMotorConfig(const common::ConfigNode& root, const common::VehicleSettings& vehicle);

}  // namespace ifar::motor
