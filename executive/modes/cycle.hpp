#pragma once
// What the executive's parts work with in one control cycle: the inputs as they stand at `now`, read once
// by the mode machine, and the motion a part asks for.

#include <cstdint>
#include <optional>
#include <string>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "common/span.hpp"
#include "executive/kinematics/velocity_command.hpp"
#include "executive/modes/inputs.hpp"
#include "executive/modes/odometer.hpp"

namespace ifar::executive {

/// True when a value stamped `stamp_us` is at most `threshold_s` old at `now_us`.
inline bool isFresh(std::int64_t now_us, std::int64_t stamp_us, double threshold_s)
{
  return static_cast<double>(now_us - stamp_us) <= threshold_s * 1e6;
}

/// The inputs of one cycle as the parts use them.
struct CycleView {
  std::int64_t now_us = 0;
  geometry::Pose2 pose;
  double force_n = 0.0;  ///< bumper force; 0 when the sensor reports a fault
  /// Fresh obstacle points, world frame; empty when they are stale (nothing is then in the way).
  common::Span<const geometry::Point> obstacles;
  bool obstacles_fresh = false;
  std::optional<ObjectObservation> pushed_object;  ///< a fresh observation of a pushed object
  /// Where the wheels have taken the vehicle, while odometry is fresh (none: judge motion on the pose).
  std::optional<WheelTrack> wheels;
};

/// What a part asks of the vehicle this cycle, and why (EXEC_STATUS's reason).
struct MotionRequest {
  VelocityCommand command;
  std::string reason;
};

}  // namespace ifar::executive
