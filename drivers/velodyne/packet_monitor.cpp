#include "drivers/velodyne/packet_monitor.hpp"

#include <cmath>

namespace ifar::velodyne {
namespace {
// A gap longer than this is a sensor restart, a clock jump or a pause in a replay, not packet loss.
constexpr double kLongestGapCountedAsDropsUs = 1'000'000.0;
}  // namespace

double packetIntervalMicroseconds(ReturnMode mode)
{
  const double firing_blocks = mode == ReturnMode::kDual ? kBlocksPerPacket / 2.0 : kBlocksPerPacket;
  return firing_blocks * kBlockDurationMicroseconds;
}

void PacketMonitor::recordValid(const PacketInfo& info)
{
  ++counts_.packets_valid;
  const std::uint32_t now = info.device_time_past_hour;
  if (has_previous_time_) {
    // Timestamps restart at the top of each hour; the forward difference handles that wrap.
    const std::uint32_t forward = now >= previous_time_past_hour_
                                      ? now - previous_time_past_hour_
                                      : now + (kMicrosecondsPerHour - previous_time_past_hour_);
    const double gap = static_cast<double>(forward);
    if (gap > kLongestGapCountedAsDropsUs || now >= kMicrosecondsPerHour) {
      ++counts_.timestamp_jumps;
    } else {
      const double intervals = std::round(gap / packetIntervalMicroseconds(info.return_mode));
      if (intervals > 1.0) {
        counts_.dropped_packets += static_cast<std::int64_t>(intervals) - 1;
      }
    }
  }
  previous_time_past_hour_ = now;
  has_previous_time_ = true;
}

void PacketMonitor::recordBad(const std::string& reason)
{
  ++counts_.bad_packets;
  counts_.last_error = reason;
  for (auto& [known, count] : bad_reasons_) {
    if (known == reason) {
      ++count;
      return;
    }
  }
  if (bad_reasons_.size() < kMostReasonsKept) {
    bad_reasons_.emplace_back(reason, 1);
  } else {
    ++other_bad_reasons_;
  }
}

std::string PacketMonitor::badSummary() const
{
  std::string text;
  for (const auto& [reason, count] : bad_reasons_) {
    text += (text.empty() ? "" : "; ") + std::to_string(count) + " x " + reason;
  }
  if (other_bad_reasons_ > 0) {
    text += "; " + std::to_string(other_bad_reasons_) + " x other reasons";
  }
  return text;
}

std::int64_t PacketMonitor::takeValidSinceLastReport()
{
  const std::int64_t since = counts_.packets_valid - valid_at_last_report_;
  valid_at_last_report_ = counts_.packets_valid;
  return since;
}

}  // namespace ifar::velodyne
