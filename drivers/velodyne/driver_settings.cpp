#include "drivers/velodyne/driver_settings.hpp"

#include <arpa/inet.h>

namespace ifar::velodyne {

const common::ParameterTable<DriverSettings>& driverParameters()
{
  using S = DriverSettings;
  using Range = common::ParameterRange;
  const Range port = Range::between(1, 65535);
  static const auto table =
      common::ParameterTable<S>()
          .add("bind_address", &S::bind_address, "", Range::any(), "local IPv4 address to receive on")
          .add("sensor_address", &S::sensor_address, "", Range::any(),
               "IPv4 address of the sensor: datagrams from any other source are counted as bad and "
               "skipped, so a simulator or second sensor on the network cannot feed this vehicle; empty "
               "accepts every source")
          .add("data_port", &S::data_port, "", port, "VLP-16 data packets (1206-byte payloads)")
          .choice(
              "sensor_model", &S::sensor_model,
              {{"auto", SensorModel::kAuto}, {"VLP-16", SensorModel::kVlp16}},
              "auto: only packets whose product byte is 0x22 (VLP-16) are decoded; VLP-16: every packet is "
              "decoded as VLP-16 whatever its product byte (for a sensor or capture that mislabels it; "
              "another model's data would give wrong points), with one warning per byte seen")
          .add("position_packets", &S::position_packets, "", Range::any(),
               "also forward position packets (512 bytes) on position_channel")
          .add("position_port", &S::position_port, "", port, "VLP-16 position packets")
          .add("receive_buffer_bytes", &S::receive_buffer_bytes, "bytes", Range::between(65536, 1 << 30),
               "SO_RCVBUF: about 2.5 s of dual-return data rides out scheduling stalls")
          .add("data_channel", &S::data_channel, "", Range::any(),
               "ifar::velodyne_packet_t, one per data packet")
          .add("position_channel", &S::position_channel, "", Range::any(), "position packets")
          .add("status_channel", &S::status_channel, "", Range::any(), "ifar::velodyne_status_t")
          .add("status_period_s", &S::status_period_s, "s", Range::positive(), "status messages' period")
          .add("bad_packet_log_interval_s", &S::bad_packet_log_interval_s, "s", Range::positive(),
               "at most one bad-packet warning per interval; the rest are counted");
  return table;
}

DriverSettings loadDriverSettings(const common::ConfigNode& node)
{
  DriverSettings settings;
  driverParameters().read(node, settings);
  in_addr parsed{};
  if (inet_pton(AF_INET, settings.bind_address.c_str(), &parsed) != 1) {
    node.fail("bind_address",
              "must be an IPv4 address such as 0.0.0.0 or 192.168.1.77, got '" + settings.bind_address + "'");
  }
  if (!settings.sensor_address.empty() && inet_pton(AF_INET, settings.sensor_address.c_str(), &parsed) != 1) {
    node.fail("sensor_address", "must be empty or an IPv4 address such as 192.168.1.201, got '" +
                                    settings.sensor_address + "'");
  }
  return settings;
}

std::string awaitedPackets(const DriverSettings& settings)
{
  const std::string port = std::to_string(settings.data_port);
  return settings.sensor_address.empty() ? "lidar packets on port " + port
                                         : "lidar packets from " + settings.sensor_address + ":" + port;
}

}  // namespace ifar::velodyne
