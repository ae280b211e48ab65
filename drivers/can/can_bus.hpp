#pragma once
// The CanBus interface every CAN user talks to: SocketCAN on a vehicle, a candump log for replay, the
// LCM bridge where the kernel has no CAN, an in-memory pair in tests. Single-threaded use per object.

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/can/frame.hpp"

namespace ifar::can {

/// CAN controller error state (ISO 11898), as the kernel reports it through error frames.
enum class BusState { kActive, kWarning, kPassive, kBusOff };
const char* toString(BusState state);

/// Accepts a frame when (frame.id & mask) == (id & mask) and the frame's extended flag equals `extended`.
struct Filter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0;
  bool extended = false;
};
/// True when `filters` is empty or any filter accepts `frame`. Error frames always pass.
bool accepts(const std::vector<Filter>& filters, const Frame& frame);

struct BusCounters {
  std::int64_t frames_received = 0;  // data frames handed to the caller
  std::int64_t frames_sent = 0;
  std::int64_t error_frames = 0;  // error frames received (also handed to the caller)
  std::int64_t write_errors = 0;  // sends that failed (buffer full, bus down, bus-off)
  std::int64_t bad_frames = 0;    // frames counted and skipped (malformed, FD frames with > 8 bytes)
};

enum class IoStatus {
  kOk,           // a frame was sent or received
  kTimeout,      // nothing arrived within the timeout
  kEndOfStream,  // a log or closed peer has nothing more
  kError,        // the bus failed; `error` says why
};
const char* toString(IoStatus status);

struct ReceiveResult {
  IoStatus status = IoStatus::kTimeout;
  Frame frame;        // valid when status == kOk; may be an error frame (frame.error())
  std::string error;  // set when status == kError
};

struct SendResult {
  IoStatus status = IoStatus::kOk;
  std::string error;  // set when status == kError
};

class CanBus {
 public:
  virtual ~CanBus() = default;
  CanBus() = default;
  CanBus(const CanBus&) = delete;
  CanBus& operator=(const CanBus&) = delete;

  /// For logs and status: "vcan0", "lcm:CAN_VEHICLE", "candump:FILE", "memory:left".
  virtual std::string name() const = 0;
  virtual SendResult send(const Frame& frame) = 0;
  /// Waits up to `timeout` (zero = poll) for the next accepted frame. Error frames are returned too
  /// (and already folded into state()); callers that only want data skip frame.error().
  virtual ReceiveResult receive(std::chrono::microseconds timeout) = 0;
  /// Replaces the receive filters; empty accepts every frame.
  virtual void setFilters(const std::vector<Filter>& filters) = 0;
  virtual BusState state() const = 0;
  virtual BusCounters counters() const = 0;
};

}  // namespace ifar::can
