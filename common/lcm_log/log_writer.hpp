#pragma once
// Writes LCM log files (the format of log_reader.hpp, which lcm-logplayer, lcm-spy and `ifar replay` read)
// without liblcm: the headless runner records every message its nodes exchange, so a simulated run can
// be replayed and inspected with the same tools as a drive.

#include <cstdint>
#include <fstream>
#include <string>

#include "common/span.hpp"

namespace ifar::lcm_log {

class LogWriter {
 public:
  /// Creates (truncates) `path`; check openError() before writing.
  explicit LogWriter(const std::string& path);

  /// Why the file cannot be written; empty when it can.
  const std::string& openError() const { return open_error_; }

  /// Appends one event. False (and writeError() says why) when the channel is empty or longer than
  /// kMaxChannelLength, or the file could not be written.
  bool write(const std::string& channel, std::int64_t timestamp_us, common::ByteView data);

  std::int64_t eventCount() const { return next_event_number_; }
  const std::string& writeError() const { return write_error_; }

 private:
  std::string path_;
  std::ofstream file_;
  std::string open_error_;
  std::string write_error_;
  std::int64_t next_event_number_ = 0;
};

}  // namespace ifar::lcm_log
