#pragma once
// Health counters of the driver: what arrived, what was published, what was malformed, and packets lost
// on the way (gaps in the device timestamps). Pure bookkeeping, no I/O, so the daemon stays thin.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "drivers/velodyne/packet_format.hpp"

namespace ifar::velodyne {

/// Device-time interval between consecutive data packets: 12 firing blocks (single return) or 6 block
/// pairs (dual return) of 110.592 us each.
double packetIntervalMicroseconds(ReturnMode mode);

struct MonitorCounts {
  std::int64_t packets_received = 0;  // datagrams read
  std::int64_t packets_valid = 0;     // data packets that passed validation
  std::int64_t bad_packets = 0;       // malformed, counted and skipped
  std::int64_t dropped_packets = 0;   // missing packets inferred from device timestamp gaps
  std::int64_t timestamp_jumps = 0;   // gaps too long (or backwards) to be counted as drops
  std::string last_error;             // the most recent bad-input reason, "" when none
};

class PacketMonitor {
 public:
  /// A datagram arrived (valid or not).
  void recordReceived() { ++counts_.packets_received; }

  /// A valid data packet: updates drop detection from its device timestamp.
  void recordValid(const PacketInfo& info);

  /// A malformed datagram; `reason` becomes last_error.
  void recordBad(const std::string& reason);

  const MonitorCounts& counts() const { return counts_; }

  /// Valid packets since the previous call (for packets per second over a report interval).
  std::int64_t takeValidSinceLastReport();

  /// Bad input so far by reason, in order of first appearance, e.g. "84 x data packet (1206 bytes): ...";
  /// "" when there was none. Reasons past the first kMostReasonsKept are counted as "other".
  std::string badSummary() const;

  static constexpr std::size_t kMostReasonsKept = 8;  // bounded: a reason may hold a size or an address

 private:
  MonitorCounts counts_;
  std::vector<std::pair<std::string, std::int64_t>> bad_reasons_;
  std::int64_t other_bad_reasons_ = 0;
  std::int64_t valid_at_last_report_ = 0;
  bool has_previous_time_ = false;
  std::uint32_t previous_time_past_hour_ = 0;
};

}  // namespace ifar::velodyne
