#pragma once
// The driver's node core: each datagram is checked, counted and, when valid, returned as the raw
// velodyne_packet_t to publish; bad ones are counted, logged at a rate limit and skipped. No bus here: the
// daemon (driver_main.cpp) publishes what it returns, the headless runner (system/) delivers it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "common/rate_limiter.hpp"
#include "common/span.hpp"
#include "drivers/velodyne/driver_settings.hpp"
#include "drivers/velodyne/packet_monitor.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "ifar/velodyne_status_t.hpp"

namespace ifar::velodyne {

/// A packet to publish and the channel it goes on. A data packet whose product byte the configured
/// sensor_model overrode is published with the product byte 0x22 (VLP-16), so every consumer decodes it
/// the way the driver accepted it; the byte it came with is named in a warning, once per byte.
struct ForwardedPacket {
  std::string channel;
  ifar::velodyne_packet_t packet;
};

class PacketForwarder {
 public:
  /// `logger` must not be null.
  PacketForwarder(const DriverSettings& settings, std::shared_ptr<spdlog::logger> logger);

  /// One datagram that arrived on `port` at host time `receive_time_us` (microseconds since the epoch):
  /// the message to publish, or nothing when the datagram was refused (counted and logged).
  std::optional<ForwardedPacket> onDatagram(std::uint16_t port, common::ByteView payload,
                                            std::int64_t receive_time_us);

  /// Whether a datagram from `source_address` (IPv4, host byte order) comes from the configured sensor
  /// (DriverSettings::sensor_address; any source when it is empty). One from elsewhere is counted as bad
  /// and logged (rate limited); the caller skips it.
  bool acceptsSource(std::uint32_t source_address, std::int64_t now_us);

  /// A datagram too large for the receive buffer (`wire_size` bytes): counted as bad and skipped.
  void onOversizedDatagram(std::uint16_t port, std::size_t wire_size, std::int64_t now_us);

  /// The status report (velodyne_status_t, for DriverSettings::status_channel) at `now_us`; `interval_s`
  /// is the time since the previous report. Also logs (debug) the latency from host receive time to
  /// `published_us` of the packets over the interval: p50, p99, max.
  ifar::velodyne_status_t statusReport(double interval_s, std::int64_t now_us);
  /// Notes when a forwarded packet actually left (for the latency report).
  void notePublished(std::int64_t receive_time_us, std::int64_t published_us);

  const PacketMonitor& monitor() const { return monitor_; }

 private:
  void reject(const std::string& reason, std::int64_t now_us);
  ForwardedPacket forward(const std::string& channel, std::uint16_t port, common::ByteView payload,
                          std::int64_t receive_time_us, std::uint32_t device_time_past_hour);

  DriverSettings settings_;
  std::optional<std::uint32_t> sensor_address_;  // host byte order; empty: any source
  std::shared_ptr<spdlog::logger> logger_;
  PacketMonitor monitor_;
  ProductOverrideNotices product_notices_;
  common::RateLimiter bad_packet_log_limiter_;
  std::vector<std::int64_t> publish_latencies_us_;  // this report interval's receive-to-publish times
};

}  // namespace ifar::velodyne
