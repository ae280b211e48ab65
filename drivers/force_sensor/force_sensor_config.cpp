#include "drivers/force_sensor/force_sensor_config.hpp"

#include <cstdint>

namespace ifar::force_sensor {

ForceSensorConfig loadForceSensorConfig(const common::ConfigNode& root)
{
  ForceSensorConfig config;
  const auto sensor = root.child("force_sensor");
  const int frame_id = sensor.required<int>("frame_id");
  if (frame_id < 0 || frame_id > 0x7FF) {
    sensor.fail("frame_id", "must be a standard id, 0..2047 (0x7FF)");
  }
  config.monitor.frame_id = static_cast<std::uint32_t>(frame_id);
  const int silence_ms = sensor.optional<int>("silence_timeout_ms", 50);
  if (silence_ms <= 0) {
    sensor.fail("silence_timeout_ms", "must be positive");
  }
  config.monitor.silence_timeout_us = silence_ms * 1000LL;
  config.monitor.stuck_counter_frames = sensor.optional<int>("stuck_counter_frames", 3);
  if (config.monitor.stuck_counter_frames < 2) {
    sensor.fail("stuck_counter_frames", "must be at least 2");
  }
  config.channel = sensor.optional<std::string>("channel", config.channel);
  return config;
}

}  // namespace ifar::force_sensor
