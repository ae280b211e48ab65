#pragma once
// Settings of ifar-velodyne-driver, read from config/velodyne.yaml.

#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "drivers/velodyne/packet_format.hpp"

namespace ifar::velodyne {

struct DriverSettings {
  std::string bind_address = "0.0.0.0";  // local IPv4 address the sockets bind
  std::string sensor_address;            // IPv4 of the sensor; datagrams from elsewhere are refused; "" any
  std::uint16_t data_port = 2368;        // VLP-16 data packets
  SensorModel sensor_model = SensorModel::kAuto;  // kVlp16: the product byte is a label (see inspectPacket)
  bool position_packets = false;                  // also forward position packets
  std::uint16_t position_port = 8308;
  std::int64_t receive_buffer_bytes = 4 * 1024 * 1024;  // SO_RCVBUF: rides out scheduling stalls
  std::string data_channel = "VELODYNE_PACKET";
  std::string position_channel = "VELODYNE_POSITION";
  std::string status_channel = "VELODYNE_STATUS";
  double status_period_s = 1.0;
  double bad_packet_log_interval_s = 1.0;  // at most one warning per interval; the rest are counted
};

/// velodyne.yaml's keys, every one optional.
const common::ParameterTable<DriverSettings>& driverParameters();

/// Reads every key of the driver's section (all optional, defaults above). Throws ConfigError naming the
/// key for a wrong type or a value out of range (ports 1..65535, positive periods).
DriverSettings loadDriverSettings(const common::ConfigNode& node);

/// What the driver waits for, as its heartbeat names it: "lidar packets from 192.168.1.201:2368", or
/// "lidar packets on port 2368" when any source is taken.
std::string awaitedPackets(const DriverSettings& settings);

}  // namespace ifar::velodyne
