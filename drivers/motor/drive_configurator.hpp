#pragma once
// Writes a list of objects into one drive by SDO expedited download, one transfer at a time (a CANopen
// server serves one SDO transfer at a time), and says when all of them are confirmed. An answer later
// than the timeout is aborted (0x05040000 on 0x600 + n) and the write repeated, up to `attempts` times;
// an abort from the drive, or a write never answered, fails the configuration with a message naming the
// object, the value and the abort code, and the whole list starts over after `retry_us`. Pure: answers
// and time in, frames out.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/can/frame.hpp"
#include "drivers/motor/sdo.hpp"

namespace ifar::motor {

struct DriveConfiguratorSettings {
  std::uint8_t node_id = 1;
  std::vector<SdoWrite> writes;       // in order; empty = nothing to configure
  std::int64_t timeout_us = 50'000;   // per transfer
  int attempts = 3;                   // per object
  std::int64_t retry_us = 1'000'000;  // after a failure, start over this much later
};

class DriveConfigurator {
 public:
  explicit DriveConfigurator(DriveConfiguratorSettings settings);

  /// The drive restarted (boot-up): what it was told is gone, configure it again from the first object.
  void restart();
  /// An SDO answer from this drive. Answers to anything but the transfer in flight are ignored.
  void onAnswer(const SdoAnswer& answer, std::int64_t now_us);
  /// Frames to send now: the next request, or an abort and the repeat of a timed-out one.
  std::vector<can::Frame> update(std::int64_t now_us);

  /// Every write confirmed since the last restart().
  bool done() const { return next_ >= settings_.writes.size(); }
  /// The last attempt failed and the configuration waits to start over.
  bool failed() const { return failed_at_us_.has_value(); }
  /// Why the last attempt failed; empty when none failed since the last success.
  const std::string& error() const { return error_; }
  /// Transfers repeated after a timeout, and configurations that failed, since construction.
  std::int64_t timeouts() const { return timeouts_; }
  std::int64_t failures() const { return failures_; }

 private:
  void fail(std::string error, std::int64_t now_us);
  std::string describe(const SdoWrite& write) const;

  DriveConfiguratorSettings settings_;
  std::size_t next_ = 0;  // index of the write in flight or to send
  int attempt_ = 0;       // attempts of writes_[next_] made so far
  std::optional<std::int64_t> sent_at_us_;
  std::optional<std::int64_t> failed_at_us_;
  std::string error_;
  std::int64_t timeouts_ = 0;
  std::int64_t failures_ = 0;
};

}  // namespace ifar::motor
