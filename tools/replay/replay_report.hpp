#pragma once
// What `ifar replay` tells its user while it plays and when it ends: how far through the log it is (time in
// the log, percent of its bytes), what it published and what it left out, per channel for the commands.

#include <cstdint>
#include <map>
#include <string>

#include "tools/replay/replay_filter.hpp"

namespace ifar::replay {

class ReplayReport {
 public:
  /// Counts one event of `channel` that got `verdict`.
  void count(const std::string& channel, Verdict verdict);

  /// One status line, e.g. "log 12.3 s, 27%, 1234 published, 56 commands left out, paused": `log_elapsed_us`
  /// is the played event's time after the log's first one; `position` of `size` bytes read.
  std::string progressLine(std::int64_t log_elapsed_us, std::uint64_t position, std::uint64_t size,
                           bool paused) const;

  /// The closing lines: totals, and each channel whose commands were left out with how many.
  std::string summary() const;

  std::uint64_t published() const { return published_; }
  std::uint64_t leftOutCommands() const { return commands_; }

 private:
  std::uint64_t published_ = 0;
  std::uint64_t not_selected_ = 0;
  std::uint64_t commands_ = 0;
  std::map<std::string, std::uint64_t> commands_by_channel_;
};

}  // namespace ifar::replay
