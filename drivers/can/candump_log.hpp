#pragma once
// The can-utils `candump -l` log format, so our logs open in can-utils (log2asc, canplayer) and theirs
// replay through us. One frame a line:
//   (1700000000.010000) can0 201#00E8030000000000
//   (1700000000.020000) can0 12345678#DEAD          extended id: 8 hex digits
//   (1700000000.030000) can0 123#R                  remote frame (optionally R<dlc>)
//   (1700000000.040000) can0 20000040#0000000000000000   error frame: id with CAN_ERR_FLAG 0x20000000
// CAN FD lines (ID##...) and anything malformed are reported as such and skipped by the reader.

#include <cstdint>
#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "drivers/can/can_bus.hpp"

namespace ifar::can {

enum class LineStatus { kOk, kBlank, kMalformed, kUnsupportedFd };

struct ParsedLine {
  LineStatus status = LineStatus::kMalformed;
  Frame frame;            // with timestamp_us from the line, when kOk
  std::string interface;  // "can0", when kOk
  std::string problem;    // why the line was rejected
};

/// Parses one log line (without or with trailing newline). Never throws.
ParsedLine parseCandumpLine(std::string_view line);
/// Formats one frame as a log line, without newline.
std::string formatCandumpLine(const Frame& frame, const std::string& interface);

/// CanBus over candump logs: receive() replays `input` line by line as fast as asked (skipping and
/// counting bad lines; kEndOfStream at the end), send() appends to `output`. Either may be null.
class CandumpLogBus final : public CanBus {
 public:
  CandumpLogBus(std::unique_ptr<std::istream> input, std::unique_ptr<std::ostream> output,
                std::string interface = "can0");
  /// Opens files by path ("" = none); error set (and bus null) when a file cannot be opened.
  struct OpenResult {
    std::unique_ptr<CandumpLogBus> bus;
    std::string error;
  };
  static OpenResult open(const std::string& input_path, const std::string& output_path,
                         const std::string& interface = "can0");

  std::string name() const override { return "candump:" + interface_; }
  SendResult send(const Frame& frame) override;
  ReceiveResult receive(std::chrono::microseconds timeout) override;
  void setFilters(const std::vector<Filter>& filters) override { filters_ = filters; }
  BusState state() const override { return state_; }
  BusCounters counters() const override { return counters_; }

 private:
  std::unique_ptr<std::istream> input_;
  std::unique_ptr<std::ostream> output_;
  std::string interface_;
  std::vector<Filter> filters_;
  BusState state_ = BusState::kActive;
  BusCounters counters_;
};

}  // namespace ifar::can
