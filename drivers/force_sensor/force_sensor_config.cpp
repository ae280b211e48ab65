#include "drivers/force_sensor/force_sensor_config.hpp"

#include <cstdint>

namespace ifar::force_sensor {

const common::ParameterTable<ForceSensorConfig>& forceSensorParameters()
{
  using S = ForceSensorConfig;
  using Range = common::ParameterRange;
  constexpr std::int64_t kMicrosecondsPerMillisecond = 1000;
  static const auto table =
      common::ParameterTable<S>()
          .add(
              "frame_id", [](auto& s) -> auto& { return s.monitor.frame_id; }, "", Range::between(0, 0x7FF),
              "standard CAN id of the sensor's frames (0x190 = 400)")
          .required()
          .converted<std::int64_t>(
              "silence_timeout_ms", "ms", Range::atLeast(1), "no valid frame for this long = silent sensor",
              [](const S& s) { return s.monitor.silence_timeout_us / kMicrosecondsPerMillisecond; },
              [](S& s, std::int64_t milliseconds) {
                s.monitor.silence_timeout_us = milliseconds * kMicrosecondsPerMillisecond;
              })
          .add(
              "stuck_counter_frames", [](auto& s) -> auto& { return s.monitor.stuck_counter_frames; }, "",
              Range::atLeast(2), "this many frames with one counter value = hung sensor")
          .add("channel", &S::channel, "", Range::nonEmpty(), "force_t");
  return table;
}

ForceSensorConfig loadForceSensorConfig(const common::ConfigNode& root)
{
  ForceSensorConfig config;
  forceSensorParameters().read(root.child("force_sensor"), config);
  return config;
}

}  // namespace ifar::force_sensor
