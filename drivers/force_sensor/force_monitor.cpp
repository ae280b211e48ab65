#include "drivers/force_sensor/force_monitor.hpp"

namespace ifar::force_sensor {

FrameVerdict ForceMonitor::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  const DecodeResult decoded = decodeForceFrame(frame, settings_.frame_id);
  if (decoded.status == DecodeStatus::kWrongId || decoded.status == DecodeStatus::kNotDataFrame) {
    return FrameVerdict::kIgnored;
  }
  if (decoded.status != DecodeStatus::kOk) {
    ++last_.frames_bad;
    return FrameVerdict::kBad;
  }
  const ForceReading& reading = decoded.reading;
  if (has_frame_) {
    const auto step = static_cast<std::uint8_t>(reading.counter - last_.counter);
    if (step == 0) {
      ++same_counter_frames_;
    } else {
      same_counter_frames_ = 1;
      last_.frames_lost += step - 1;
    }
  } else {
    same_counter_frames_ = 1;
  }
  has_frame_ = true;
  last_frame_us_ = now_us;
  last_.receive_time_us = now_us;
  last_.force_newtons = reading.force_newtons;
  last_.counter = reading.counter;
  std::int32_t status = 0;
  if (reading.overload)
    status |= kHealthOverload;
  if (reading.fault)
    status |= kHealthFault;
  if (same_counter_frames_ >= settings_.stuck_counter_frames)
    status |= kHealthCounterStuck;
  last_.status = status;
  return FrameVerdict::kAccepted;
}

ForceSample ForceMonitor::sample(std::int64_t now_us) const
{
  ForceSample result = last_;
  if (!has_frame_ || now_us - last_frame_us_ > settings_.silence_timeout_us) {
    result.status |= kHealthSilent;
  }
  return result;
}

}  // namespace ifar::force_sensor
