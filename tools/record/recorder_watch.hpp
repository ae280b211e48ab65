#pragma once
// Whether the recorder is doing its job, for its heartbeat: lcm-logger running, and its log file growing
// while messages it should record arrive. A logger that is killed, or that is alive but writes nothing (a
// full disk, a stalled file system, a stopped process), would otherwise go unnoticed until someone needs the
// log. No clock or process of its own: `ifar record` tells it what it sees, with the time.
//
// It is ready (OK) only once lcm-logger is known to record: its file has grown after a message arrived,
// the recorder's own heartbeat as the first. Until then it is DEGRADED, so `ifar launch` holds back the
// processes that start after it, and their first messages are in the log. When nothing that is recorded
// arrives (the channels leave out HEARTBEAT) it is OK a second after the file opened: nothing is lost.

#include <cstdint>
#include <optional>
#include <string>

namespace ifar::record {

struct RecorderHealth {
  std::int8_t level = 0;  // heartbeat_t::HEALTH_OK, HEALTH_DEGRADED (not yet recording) or HEALTH_ERROR
  std::string message;    // empty when OK, else what is wrong
};

class RecorderWatch {
 public:
  /// Messages unwritten for `stall_after_us` (no growth of the file since one arrived) are an error.
  explicit RecorderWatch(std::int64_t stall_after_us) : stall_after_us_(stall_after_us) {}

  /// A message lcm-logger should record arrived (the recorder subscribes to the same channels).
  void onMessage(std::int64_t now_us);
  /// lcm-logger opened `path` (at start, and at each split or rotation).
  void onLogFile(const std::string& path, std::int64_t now_us);
  /// The current file's size, or nothing when it cannot be read (removed, unreadable).
  void onFileSize(std::optional<std::uint64_t> size, std::int64_t now_us);
  /// lcm-logger ended; `how` says how, e.g. "killed by signal 9 (Killed)".
  void onLoggerExit(const std::string& how);

  RecorderHealth health(std::int64_t now_us) const;
  const std::string& logFile() const { return path_; }

 private:
  std::int64_t stall_after_us_;
  std::string path_;
  std::optional<std::int64_t> opened_us_;  // when the first file opened
  bool recording_ = false;
  std::optional<std::uint64_t> size_;
  bool size_unreadable_ = false;
  std::optional<std::string> exit_;
  std::int64_t unwritten_messages_ = 0;  // arrived since the file last grew
  std::optional<std::int64_t> first_unwritten_us_;
};

}  // namespace ifar::record
