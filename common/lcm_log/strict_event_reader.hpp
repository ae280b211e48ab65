#pragma once
// Reading a log for tools that pass its events on (ifar replay publishes them, ifar echo prints them) and
// must not pass on a damaged one. LogReader skips what is not an event and carries on; this stops at the
// first problem. It also hands out each event only once the bytes after it are seen to start the next event
// or end the file: a data length made larger by a flipped bit swallows the start of the next event and still
// reads as an event, which shows only as a bad sync word where the next should start. Such an event is
// left out and named.

#include <cstdint>
#include <string>

#include "common/lcm_log/log_reader.hpp"

namespace ifar::lcm_log {

class StrictEventReader {
 public:
  /// Reads from `reader` (opened, not yet read), which must outlive this object.
  explicit StrictEventReader(LogReader& reader) : reader_(reader) {}

  /// The next event whose end is confirmed: false at the end of the log or at the first problem.
  bool next(LogEvent& event);

  /// Why reading stopped before the end, e.g. "byte 62171: bad sync word 0x00000000; ...; the event at byte
  /// 62097 before it is left out: its length does not end where an event starts"; empty when it did not.
  std::string problem() const;

 private:
  LogReader& reader_;
  bool started_ = false;
  bool has_current_ = false;
  LogEvent current_;
  LogEvent upcoming_;
  std::uint64_t current_start_ = 0;
  bool held_back_ = false;  // the last event read was left out for its suspect length
  std::uint64_t held_back_start_ = 0;
};

}  // namespace ifar::lcm_log
