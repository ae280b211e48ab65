#include "drivers/force_sensor/force_driver_node.hpp"

#include <utility>

namespace ifar::force_sensor {
namespace {

constexpr std::int64_t kBadFrameLogIntervalUs = 1'000'000;

}  // namespace

ifar::force_t toForceMessage(const ForceSample& sample, std::int64_t utime)
{
  ifar::force_t message{};
  message.utime = utime;
  message.force_n = static_cast<float>(sample.force_newtons);
  message.counter = sample.counter;
  message.status = sample.status;
  message.frames_bad = sample.frames_bad;
  return message;
}

ForceDriverNode::ForceDriverNode(const ForceMonitorSettings& settings, std::shared_ptr<spdlog::logger> logger)
    : settings_(settings),
      logger_(std::move(logger)),
      monitor_(settings),
      bad_frame_log_(kBadFrameLogIntervalUs)
{
}

void ForceDriverNode::noteStatus(std::int32_t status)
{
  if (status == last_status_) {
    return;
  }
  if ((status & kHealthSilent) != 0) {
    logger_->warn("force sensor silent: no valid frame for {} ms", settings_.silence_timeout_us / 1000);
  } else {
    logger_->info("force sensor status {} -> {}", last_status_, status);
  }
  last_status_ = status;
}

std::optional<ifar::force_t> ForceDriverNode::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  const FrameVerdict verdict = monitor_.onFrame(frame, now_us);
  if (verdict == FrameVerdict::kIgnored) {
    ++unknown_frames_;
    return std::nullopt;
  }
  if (verdict == FrameVerdict::kBad) {
    if (bad_frame_log_.allow(now_us)) {
      logger_->warn("bad force sensor frame (dlc {}) skipped; {} bad so far", frame.dlc,
                    monitor_.sample(now_us).frames_bad);
    }
    return std::nullopt;
  }
  const ForceSample sample = monitor_.sample(now_us);
  noteStatus(sample.status);
  return toForceMessage(sample, frame.timestamp_us);
}

std::optional<ifar::force_t> ForceDriverNode::silenceReport(std::int64_t now_us)
{
  const ForceSample sample = monitor_.sample(now_us);
  if ((sample.status & kHealthSilent) == 0 ||
      now_us - last_silent_report_us_ < settings_.silence_timeout_us) {
    return std::nullopt;
  }
  last_silent_report_us_ = now_us;
  noteStatus(sample.status);
  return toForceMessage(sample, now_us);
}

}  // namespace ifar::force_sensor
