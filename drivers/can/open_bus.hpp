#pragma once
// Which CanBus a daemon uses, from its config (config/can.yaml `bus:` section):
//   bus:
//     kind: socketcan          # socketcan | lcm | candump
//     interface: can0          # socketcan: the interface
//     bitrate: 500000          # socketcan: bit/s (ifar can up brings the interface up with it)
//     restart_ms: 100          # socketcan: bus-off recovery
//     lcm_channel: CAN_VEHICLE # lcm: the can_frame_t channel
//     candump_input: ""        # candump: log to replay
//     candump_output: ""       # candump: log to append sent frames to
// Part of ifar_can_lcm_bridge (it can open the LCM bridge), so daemons only.

#include <cstdint>
#include <memory>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "drivers/can/can_bus.hpp"

namespace ifar::can {

enum class BusKind { kSocketCan, kLcm, kCandump };
const char* toString(BusKind kind);

struct BusSettings {
  BusKind kind = BusKind::kLcm;
  std::string interface = "can0";
  std::int64_t bitrate = 500000;  // socketcan: bit/s the interface is brought up with (ifar can up)
  std::int64_t restart_ms = 100;  // socketcan: bus-off recovery after this long; 0 = stay off
  std::string lcm_channel = "CAN_VEHICLE";
  std::string candump_input;
  std::string candump_output;
};

/// can.yaml `bus:` keys: the kind required, the rest optional.
const common::ParameterTable<BusSettings>& busParameters();

/// Reads the `bus` child of `root`. Throws common::ConfigError naming the key for a bad kind.
BusSettings loadBusSettings(const common::ConfigNode& root);

/// can.yaml's top-level channels: where a socketcan or candump daemon republishes the bus.
struct BusChannels {
  std::string raw_channel = "CAN_VEHICLE";
  std::string status_channel = "CAN_STATUS";
};
const common::ParameterTable<BusChannels>& busChannelParameters();

struct OpenBusResult {
  std::unique_ptr<CanBus> bus;  // null on failure
  std::string error;
};

/// Opens the configured bus. `lcm` is used (and must outlive the bus) only for kind lcm.
OpenBusResult openBus(const BusSettings& settings, lcm::LCM& lcm);

}  // namespace ifar::can
