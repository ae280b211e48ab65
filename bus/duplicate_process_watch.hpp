#pragma once
// A second daemon of the same name on one LCM URL (a second stack started on the same host, a log replayed
// onto the vehicle's bus) would feed every other node two voices. Each daemon watches the heartbeats of its
// own name: one with another process id means someone else is speaking for it.

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace ifar::bus {

class DuplicateProcessWatch {
 public:
  /// `process`: this daemon's name in its heartbeats; `own_pid`: its process id (its own beats come back
  /// to it and are not a duplicate). Another process counts as present for `forget_after_us` after its
  /// last beat.
  DuplicateProcessWatch(std::string process, std::int32_t own_pid, std::int64_t forget_after_us = 3'000'000);

  /// A heartbeat seen on the bus at `now_us`. Returns the alarm to log when it comes from a process of
  /// this name not seen (or forgotten) before.
  std::optional<std::string> onBeat(const std::string& process, std::int32_t pid, std::int64_t now_us);

  /// What to report in this daemon's own heartbeat while another of its name is present; empty when none.
  std::string problem(std::int64_t now_us) const;

 private:
  std::string process_;
  std::int32_t own_pid_;
  std::int64_t forget_after_us_;
  std::map<std::int32_t, std::int64_t> others_;  // pid -> last beat seen
};

}  // namespace ifar::bus
