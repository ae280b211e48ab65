#pragma once
// A reader for LCM log files (what lcm-logger writes) that trusts nothing in the file. liblcm 1.3.1's
// reader mallocs whatever length an event header claims and freads into the result unchecked, so one
// corrupt header crashed every tool that read the log; it also stops without a word at the first header
// it does not like, which made garbage look like a short, clean log. This reader checks each claimed
// length against the bytes left in the file before allocating anything, resynchronises on the next sync
// word after bytes that are not an event (as liblcm does), and records every problem with its byte
// offset, so a checker can fail and the other tools can warn.
//
// The format is bytes only, no LCM needed (https://lcm-proj.github.io/lcm/content/log-file-format.html):
// each event is, big-endian, the sync word 0xEDA1DA01, int64 event number, int64 timestamp (microseconds
// since the epoch), int32 channel length, int32 data length, then the channel bytes and the data bytes.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ifar::lcm_log {

constexpr std::uint32_t kSyncWord = 0xEDA1DA01U;
constexpr std::uint64_t kHeaderSize = 28;  // sync word, event number, timestamp, two lengths
/// liblcm's reader rejects channel lengths outside 1..999 (lcm/eventlog.c); the same bound here, so a log
/// one reader accepts the other does too.
constexpr std::int32_t kMaxChannelLength = 999;

/// One event of the log, with its own copies of the channel and data bytes.
struct LogEvent {
  std::int64_t event_number = 0;
  std::int64_t timestamp_us = 0;
  std::string channel;
  std::vector<std::uint8_t> data;
};

enum class LogProblemKind : std::uint8_t {
  kBadSyncWord,       // bytes that do not start an event: skipped up to the next sync word
  kTruncatedHeader,   // the file ends inside an event header
  kTruncatedEvent,    // the header claims more channel and data bytes than the file has left
  kBadChannelLength,  // channel length outside 1..kMaxChannelLength
  kBadDataLength,     // negative data length
  kReadError,         // the stream failed before the end of the file (the file shrank, an I/O error)
};

const char* toString(LogProblemKind kind);

struct LogProblem {
  LogProblemKind kind = LogProblemKind::kBadSyncWord;
  std::uint64_t offset = 0;  // byte offset in the file of the bad header or of the first bad byte
  /// Says where and what, e.g. "byte 0: event truncated: header claims 4 channel and 2147483647 data
  /// bytes, only 108 bytes follow the header; skipped 136 bytes to the end of the file".
  std::string description;
};

class LogReader {
 public:
  /// How many problems problems() keeps; problemCount() counts them all.
  static constexpr std::size_t kMaxKeptProblems = 10;

  /// Opens a file; check openError() before reading.
  static LogReader open(const std::string& path);

  /// Reads from any seekable stream (an std::istringstream in tests); takes ownership.
  explicit LogReader(std::unique_ptr<std::istream> stream);

  /// Why the log cannot be read at all (missing, a directory, unreadable, not seekable); empty otherwise.
  const std::string& openError() const { return open_error_; }

  /// Reads the next valid event into `event` (its buffers are reused): false at the end of the file.
  /// Bytes that are not a valid event are skipped and recorded as problems on the way.
  bool next(LogEvent& event);

  std::uint64_t fileSize() const { return file_size_; }
  /// The offset of the next byte next() reads: with fileSize(), how far through the log a reader is.
  std::uint64_t position() const { return position_; }
  /// Events next() returned so far.
  std::uint64_t eventCount() const { return event_count_; }
  /// Bytes that belonged to no valid event, so far.
  std::uint64_t skippedBytes() const { return skipped_bytes_; }
  std::uint64_t problemCount() const { return problem_count_; }
  /// The first kMaxKeptProblems problems, in file order.
  const std::vector<LogProblem>& problems() const { return problems_; }
  bool clean() const { return problem_count_ == 0; }
  /// One line for a warning, e.g. "2 problems, 1510 bytes skipped; first: byte 136: bad sync word ...";
  /// empty when clean.
  std::string problemSummary() const;

 private:
  explicit LogReader(std::string open_error) : open_error_(std::move(open_error)) {}
  /// Reads `count` bytes at the current stream position into `bytes`; false (and a kReadError problem)
  /// when the stream delivers fewer.
  bool readBytes(void* bytes, std::uint64_t count);
  /// The offset of the first sync word at or after `from`, or the file size when there is none.
  std::uint64_t findSyncWord(std::uint64_t from);
  /// Records a problem at `start` (a bad event header or garbage) whose bytes run to the next sync word
  /// after it, and moves there: the next event, if any, is read from that sync word on.
  void skipToNextSyncWord(std::uint64_t start, LogProblemKind kind, const std::string& what);
  void addProblem(LogProblemKind kind, std::uint64_t offset, const std::string& description);

  std::unique_ptr<std::istream> stream_;
  std::string open_error_;
  std::uint64_t file_size_ = 0;
  std::uint64_t position_ = 0;  // offset of the next byte to read
  bool finished_ = false;
  std::uint64_t event_count_ = 0;
  std::uint64_t skipped_bytes_ = 0;
  std::uint64_t problem_count_ = 0;
  std::vector<LogProblem> problems_;
};

}  // namespace ifar::lcm_log
