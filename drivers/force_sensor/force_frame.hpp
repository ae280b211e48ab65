#pragma once
// The bumper force sensor's CAN frame (spec: docs/can_frames.md, "Force sensor"): encoder and decoder.
// The simulator encodes with ForceSensorEmulator; the force driver decodes.
//
// Frame: standard id 0x190 (default; config/can.yaml), DLC 8, 100 Hz, all fields little-endian:
//   bytes 0-3  force, int32 LE, 1 LSB = 1 mN (0.001 N); positive = the bumper is pressed (pushing)
//   byte  4    status bits: bit 0 overload (range exceeded, force saturated), bit 1 fault; others 0
//   byte  5    rolling counter, +1 per frame, wraps 255 -> 0
//   byte  6    reserved, 0
//   byte  7    checksum: sum of bytes 0-6 modulo 256

#include <cstdint>

#include "drivers/can/frame.hpp"

namespace ifar::force_sensor {

constexpr std::uint32_t kDefaultFrameId = 0x190;
constexpr std::uint8_t kFrameLength = 8;
constexpr double kNewtonsPerCount = 0.001;
constexpr std::uint8_t kStatusOverload = 0x01;
constexpr std::uint8_t kStatusFault = 0x02;

struct ForceReading {
  double force_newtons = 0.0;  // normal force on the bumper, N; quantised to 1 mN on the wire
  std::uint8_t counter = 0;    // rolling frame counter
  bool overload = false;       // the sensor's range was exceeded; force_newtons is saturated
  bool fault = false;          // the sensor reports an internal fault; force_newtons is not valid
};

enum class DecodeStatus {
  kOk,
  kWrongId,       // not the sensor's id (or an extended id)
  kNotDataFrame,  // remote or error frame
  kWrongLength,   // DLC other than 8
  kBadChecksum,   // byte 7 does not match bytes 0-6
};
const char* toString(DecodeStatus status);

struct DecodeResult {
  DecodeStatus status = DecodeStatus::kOk;
  ForceReading reading;  // valid when status == kOk
};

/// Encodes `reading`; the force is rounded to 1 mN and clamped to the int32 range.
can::Frame encodeForceFrame(const ForceReading& reading, std::uint32_t frame_id = kDefaultFrameId);

/// Decodes a frame from the bus; never throws, every problem is a status.
DecodeResult decodeForceFrame(const can::Frame& frame, std::uint32_t frame_id = kDefaultFrameId);

/// The sensor as the simulator emulates it: saturates at its range (and flags overload), advances the
/// counter, and can be told to report a fault or freeze its counter (to exercise the monitor).
class ForceSensorEmulator {
 public:
  explicit ForceSensorEmulator(double range_newtons = 800.0, std::uint32_t frame_id = kDefaultFrameId)
      : range_newtons_(range_newtons), frame_id_(frame_id)
  {
  }

  /// The next frame (send one every 10 ms) for the contact force `force_newtons` (negative = 0).
  can::Frame nextFrame(double force_newtons);

  void setFault(bool fault) { fault_ = fault; }
  void setCounterFrozen(bool frozen) { counter_frozen_ = frozen; }

 private:
  double range_newtons_;
  std::uint32_t frame_id_;
  std::uint8_t counter_ = 0;
  bool fault_ = false;
  bool counter_frozen_ = false;
};

}  // namespace ifar::force_sensor
