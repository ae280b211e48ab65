#pragma once
// The daemon's core: each datagram is checked, counted and, when valid, published raw on LCM; bad ones
// are counted, logged at a rate limit and skipped. Daemon-only (includes LCM through RunLoop).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "common/bus/run_loop.hpp"
#include "common/rate_limiter.hpp"
#include "common/span.hpp"
#include "drivers/velodyne/driver_settings.hpp"
#include "drivers/velodyne/packet_monitor.hpp"

namespace ifar::velodyne {

class PacketForwarder {
 public:
  /// `loop` and `logger` must outlive this object.
  PacketForwarder(const DriverSettings& settings, bus::RunLoop& loop, std::shared_ptr<spdlog::logger> logger);

  /// One datagram that arrived on `port` at host time `receive_time_us` (microseconds since the epoch).
  void onDatagram(std::uint16_t port, common::ByteView payload, std::int64_t receive_time_us);

  /// A datagram too large for the receive buffer (`wire_size` bytes): counted as bad and skipped.
  void onOversizedDatagram(std::uint16_t port, std::size_t wire_size);

  /// Publishes velodyne_status_t; `interval_s` is the time since the previous report. Also logs (debug)
  /// the latency from host receive time to publish over the interval: p50, p99, max.
  void publishStatus(double interval_s);

  const PacketMonitor& monitor() const { return monitor_; }

 private:
  void reject(const std::string& reason);
  void publish(const std::string& channel, std::uint16_t port, common::ByteView payload,
               std::int64_t receive_time_us, std::uint32_t device_time_past_hour);

  DriverSettings settings_;
  bus::RunLoop& loop_;
  std::shared_ptr<spdlog::logger> logger_;
  PacketMonitor monitor_;
  common::RateLimiter bad_packet_log_limiter_;
  std::vector<std::int64_t> publish_latencies_us_;  // this report interval's receive-to-publish times
};

}  // namespace ifar::velodyne
