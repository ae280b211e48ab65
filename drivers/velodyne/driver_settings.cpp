#include "drivers/velodyne/driver_settings.hpp"

#include <arpa/inet.h>

namespace ifar::velodyne {
namespace {

std::uint16_t readPort(const common::ConfigNode& node, const std::string& key, std::uint16_t fallback)
{
  const int port = node.optional<int>(key, fallback);
  if (port < 1 || port > 65535) {
    node.fail(key, "must be a UDP port between 1 and 65535, got " + std::to_string(port));
  }
  return static_cast<std::uint16_t>(port);
}

}  // namespace

DriverSettings loadDriverSettings(const common::ConfigNode& node)
{
  DriverSettings settings;
  settings.bind_address = node.optional<std::string>("bind_address", settings.bind_address);
  in_addr parsed{};
  if (inet_pton(AF_INET, settings.bind_address.c_str(), &parsed) != 1) {
    node.fail("bind_address",
              "must be an IPv4 address such as 0.0.0.0 or 192.168.1.77, got '" + settings.bind_address + "'");
  }
  settings.data_port = readPort(node, "data_port", settings.data_port);
  settings.position_packets = node.optional<bool>("position_packets", settings.position_packets);
  settings.position_port = readPort(node, "position_port", settings.position_port);
  settings.receive_buffer_bytes =
      node.optional<std::int64_t>("receive_buffer_bytes", settings.receive_buffer_bytes);
  if (settings.receive_buffer_bytes < 65536 || settings.receive_buffer_bytes > (1LL << 30)) {
    node.fail("receive_buffer_bytes", "must be between 65536 and 1073741824");
  }
  settings.data_channel = node.optional<std::string>("data_channel", settings.data_channel);
  settings.position_channel = node.optional<std::string>("position_channel", settings.position_channel);
  settings.status_channel = node.optional<std::string>("status_channel", settings.status_channel);
  settings.status_period_s = node.optionalPositive("status_period_s", settings.status_period_s);
  settings.bad_packet_log_interval_s =
      node.optionalPositive("bad_packet_log_interval_s", settings.bad_packet_log_interval_s);
  return settings;
}

}  // namespace ifar::velodyne
