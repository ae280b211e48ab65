#pragma once
// The force driver's core: the sensor's CAN frames in (with their receive times), force_t out, without a
// bus. Every valid frame of the sensor becomes one force_t; while the sensor is silent, a force_t flagged
// STATUS_SILENT goes out every silence timeout, so listeners see the flag without the frames. The daemon
// (force_driver_main.cpp) wraps it around the configured CAN bus; the headless runner (system/) feeds it
// the simulator's frames on simulated time.

#include <cstdint>
#include <memory>
#include <optional>

#include <spdlog/spdlog.h>

#include "common/rate_limiter.hpp"
#include "drivers/can/frame.hpp"
#include "drivers/force_sensor/force_monitor.hpp"
#include "ifar/force_t.hpp"

namespace ifar::force_sensor {

class ForceDriverNode {
 public:
  /// `logger` receives status changes and bad-frame warnings; it must not be null.
  ForceDriverNode(const ForceMonitorSettings& settings, std::shared_ptr<spdlog::logger> logger);

  /// One data frame from the bus, `frame.timestamp_us` its receive time. The force_t to publish when it
  /// is a valid frame of the sensor; frames of other ids are counted (unknownFrames), malformed ones of the
  /// sensor's id counted and warned about (rate limited).
  std::optional<ifar::force_t> onFrame(const can::Frame& frame, std::int64_t now_us);
  /// Call often (each time the bus is drained): a STATUS_SILENT force_t once per silence timeout while no
  /// valid frame arrives.
  std::optional<ifar::force_t> silenceReport(std::int64_t now_us);

  ForceSample sample(std::int64_t now_us) const { return monitor_.sample(now_us); }
  std::int64_t unknownFrames() const { return unknown_frames_; }
  /// Bad-frame warnings held back by the rate limit since the last call.
  std::int64_t takeSuppressedWarnings() { return bad_frame_log_.takeSuppressed(); }

 private:
  void noteStatus(std::int32_t status);

  ForceMonitorSettings settings_;
  std::shared_ptr<spdlog::logger> logger_;
  ForceMonitor monitor_;
  common::RateLimiter bad_frame_log_;
  std::int64_t unknown_frames_ = 0;
  std::int64_t last_silent_report_us_ = 0;
  std::int32_t last_status_ = -1;
};

/// A sample as force_t, stamped `utime`.
ifar::force_t toForceMessage(const ForceSample& sample, std::int64_t utime);

}  // namespace ifar::force_sensor
