#pragma once
// Watches the force sensor's frame stream: decodes each frame, and flags a silent sensor (no valid
// frame for the timeout, 50 ms by default) and a stuck counter (the same counter value in several
// consecutive frames: the sensor's firmware hung while its CAN controller repeats the last frame).
// Pure (fed with frames and time), so the driver daemon and tests share it.

#include <cstdint>

#include "drivers/can/frame.hpp"
#include "drivers/force_sensor/force_frame.hpp"

namespace ifar::force_sensor {

/// Status bits; the values match ifar::force_t's STATUS_ constants.
constexpr std::int32_t kHealthOverload = 1;
constexpr std::int32_t kHealthFault = 2;
constexpr std::int32_t kHealthSilent = 4;
constexpr std::int32_t kHealthCounterStuck = 8;

struct ForceMonitorSettings {
  std::uint32_t frame_id = kDefaultFrameId;
  std::int64_t silence_timeout_us = 50'000;
  int stuck_counter_frames = 3;  // this many consecutive frames with one counter value = stuck
};

/// What the driver publishes as force_t.
struct ForceSample {
  std::int64_t receive_time_us = 0;  // receive time of the last valid frame (0 before the first)
  double force_newtons = 0.0;
  std::uint8_t counter = 0;
  std::int32_t status = kHealthSilent;  // bitwise OR of the kHealth constants
  std::int64_t frames_bad = 0;          // sensor frames skipped: wrong length, bad checksum
  std::int64_t frames_lost = 0;         // frames missed, judged by counter gaps
};

enum class FrameVerdict {
  kAccepted,  // a valid sensor frame: the sample changed
  kIgnored,   // another id (not the sensor's), or an error/remote frame: not counted here
  kBad,       // the sensor's id but malformed: counted in frames_bad
};

class ForceMonitor {
 public:
  explicit ForceMonitor(const ForceMonitorSettings& settings = {}) : settings_(settings) {}

  FrameVerdict onFrame(const can::Frame& frame, std::int64_t now_us);
  /// The current sample with the silence check applied at `now_us`.
  ForceSample sample(std::int64_t now_us) const;

 private:
  ForceMonitorSettings settings_;
  ForceSample last_;
  bool has_frame_ = false;
  std::int64_t last_frame_us_ = 0;
  int same_counter_frames_ = 0;
};

}  // namespace ifar::force_sensor
