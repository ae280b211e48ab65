#include "drivers/velodyne/packet_forwarder.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <utility>

#include "common/time.hpp"
#include "drivers/velodyne/packet_format.hpp"

namespace ifar::velodyne {

PacketForwarder::PacketForwarder(const DriverSettings& settings, std::shared_ptr<spdlog::logger> logger)
    : settings_(settings),
      logger_(std::move(logger)),
      bad_packet_log_limiter_(common::secondsToMicroseconds(settings.bad_packet_log_interval_s))
{
  in_addr sensor{};
  if (!settings.sensor_address.empty() && inet_pton(AF_INET, settings.sensor_address.c_str(), &sensor) == 1) {
    sensor_address_ = ntohl(sensor.s_addr);
  }
}

std::optional<ForwardedPacket> PacketForwarder::onDatagram(std::uint16_t port, common::ByteView payload,
                                                           std::int64_t receive_time_us)
{
  monitor_.recordReceived();
  if (port == settings_.data_port) {
    const PacketInfo info = inspectPacket(payload, settings_.sensor_model);
    if (info.status != PacketStatus::kOk) {
      reject("data packet (" + std::to_string(payload.size()) + " bytes): " + describeProblem(info),
             receive_time_us);
      return std::nullopt;
    }
    monitor_.recordValid(info);
    ForwardedPacket forwarded =
        forward(settings_.data_channel, port, payload, receive_time_us, info.device_time_past_hour);
    if (info.product_overridden) {
      if (product_notices_.firstOverride(info)) {
        logger_->warn("{}", overriddenProductWarning(info.product_byte, settings_.sensor_model));
      }
      // Consumers decode with the strict default: the label the user vouched for goes with the packet.
      forwarded.packet.data[kProductIdOffset] = static_cast<std::uint8_t>(ProductId::kVlp16);
    }
    return forwarded;
  }
  if (settings_.position_packets && port == settings_.position_port) {
    if (payload.size() != kPositionPacketSize) {
      reject("position packet: " + std::to_string(payload.size()) + " bytes, expected 512", receive_time_us);
      return std::nullopt;
    }
    // The position packet's timestamp (microseconds past the hour) sits at byte 198 (VLP-16 manual).
    constexpr std::size_t kPositionTimestampOffset = 198;
    return forward(settings_.position_channel, port, payload, receive_time_us,
                   readUint32Le(payload.data() + kPositionTimestampOffset));
  }
  reject("datagram on port " + std::to_string(port) + " that the driver does not read", receive_time_us);
  return std::nullopt;
}

void PacketForwarder::onOversizedDatagram(std::uint16_t port, std::size_t wire_size, std::int64_t now_us)
{
  monitor_.recordReceived();
  reject("datagram of " + std::to_string(wire_size) + " bytes on port " + std::to_string(port) +
             ", larger than any VLP-16 packet",
         now_us);
}

bool PacketForwarder::acceptsSource(std::uint32_t source_address, std::int64_t now_us)
{
  if (!sensor_address_ || source_address == *sensor_address_) {
    return true;
  }
  in_addr address{};
  address.s_addr = htonl(source_address);
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &address, text, sizeof(text));
  monitor_.recordReceived();
  reject(std::string("datagram from ") + text + ", not the sensor " + settings_.sensor_address, now_us);
  return false;
}

void PacketForwarder::reject(const std::string& reason, std::int64_t now_us)
{
  monitor_.recordBad(reason);
  if (bad_packet_log_limiter_.allow(now_us)) {
    const std::int64_t suppressed = bad_packet_log_limiter_.takeSuppressed();
    logger_->warn("skipping bad input: {} ({} bad so far, {} not logged since the last warning)", reason,
                  monitor_.counts().bad_packets, suppressed);
  }
}

ForwardedPacket PacketForwarder::forward(const std::string& channel, std::uint16_t port,
                                         common::ByteView payload, std::int64_t receive_time_us,
                                         std::uint32_t device_time_past_hour)
{
  ifar::velodyne_packet_t message;
  message.utime = receive_time_us;
  message.device_time_past_hour = static_cast<std::int32_t>(device_time_past_hour);
  message.port = port;
  message.size = static_cast<std::int32_t>(payload.size());
  message.data.assign(payload.begin(), payload.end());
  return ForwardedPacket{channel, std::move(message)};
}

void PacketForwarder::notePublished(std::int64_t receive_time_us, std::int64_t published_us)
{
  constexpr std::size_t kMostLatenciesKept = 100'000;  // bounded even if the status timer stalls
  if (publish_latencies_us_.size() < kMostLatenciesKept) {
    publish_latencies_us_.push_back(published_us - receive_time_us);
  }
}

ifar::velodyne_status_t PacketForwarder::statusReport(double interval_s, std::int64_t now_us)
{
  const MonitorCounts& counts = monitor_.counts();
  ifar::velodyne_status_t status;
  status.utime = now_us;
  const std::int64_t valid = monitor_.takeValidSinceLastReport();
  status.packets_per_second =
      interval_s > 0.0 ? static_cast<float>(static_cast<double>(valid) / interval_s) : 0.0F;
  status.packets_received = counts.packets_received;
  status.packets_published = counts.packets_valid;  // every valid data packet is published
  status.bad_packets = counts.bad_packets;
  status.dropped_packets = counts.dropped_packets;
  status.last_error = counts.last_error;

  if (!publish_latencies_us_.empty() && logger_->should_log(spdlog::level::debug)) {
    auto& latencies = publish_latencies_us_;
    std::sort(latencies.begin(), latencies.end());
    logger_->debug("receive-to-publish latency over {} packets: p50 {} us, p99 {} us, max {} us",
                   latencies.size(), latencies[latencies.size() / 2], latencies[latencies.size() * 99 / 100],
                   latencies.back());
  }
  publish_latencies_us_.clear();
  return status;
}

}  // namespace ifar::velodyne
