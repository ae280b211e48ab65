#pragma once
// The `force_sensor` section of config/can.yaml (library ifar_force_sensor_config; ifar_force_sensor
// itself stays free of the YAML stack). ifar-force-driver runs on it; ifar-motor-driver checks it, so a
// bad shared file stops both daemons alike.
//
//   force_sensor:
//     frame_id: 400              # standard id, 0..0x7FF
//     silence_timeout_ms: 50
//     stuck_counter_frames: 3
//     channel: FORCE

#include <string>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "drivers/force_sensor/force_monitor.hpp"

namespace ifar::force_sensor {

struct ForceSensorConfig {
  ForceMonitorSettings monitor;
  std::string channel = "FORCE";  // force_t
};

/// can.yaml `force_sensor:` keys: the frame id required, the rest optional.
const common::ParameterTable<ForceSensorConfig>& forceSensorParameters();

/// Reads root.force_sensor. Throws common::ConfigError naming the key for a frame id outside 0..0x7FF, a
/// non-positive silence timeout or fewer than 2 stuck-counter frames.
ForceSensorConfig loadForceSensorConfig(const common::ConfigNode& root);

}  // namespace ifar::force_sensor
