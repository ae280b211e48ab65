#pragma once
// What the executive reads each cycle: the latest value of every input with the time it arrived. The
// daemon fills this from LCM messages, the headless runner from the simulator; the executive only reads.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "executive/pusher/push_plan.hpp"

namespace ifar::executive {

/// A value and when it was received, microseconds (the same clock as the `now` given to step()).
template <typename T>
struct Stamped {
  T value{};
  std::int64_t utime = 0;
};

enum class WaypointKind {
  Free,         ///< reached along a collision-free segment
  Topological,  ///< a topological waypoint where a push starts
  Push,         ///< reached by executing push_plan_index
};

struct Waypoint {
  geometry::Point position = geometry::Point::Zero();
  WaypointKind kind = WaypointKind::Free;
  std::int64_t object_id = -1;
  int push_plan_index = -1;  ///< index into Path::push_plans, -1 for none
};

/// The global path (GLOBAL_PATH). The first waypoint is where the vehicle was at planning time.
struct Path {
  std::int64_t utime = 0;  ///< planning time, microseconds
  std::int64_t goal_id = -1;
  std::int64_t sequence = 0;
  bool valid = false;  ///< false: the planner found no path
  std::vector<Waypoint> waypoints;
  std::vector<PushPlan> push_plans;
};

struct ForceReading {
  double force_n = 0.0;  ///< bumper normal force, newtons
  bool faulty = false;   ///< sensor fault, silent or hung: the value means nothing
};

/// Combined state of the drive motors.
struct MotorReading {
  bool heartbeat_ok = false;
  bool fault = false;
  std::string reason;  ///< why the motor client stopped the drive, empty when running
};

/// Wheel odometry (ODOMETRY, from the drives' actual velocities): what the wheels did. Wheels keep
/// turning when they slip, and a state estimator's pose jitters by centimetres, so neither alone says the
/// vehicle moved.
struct OdometryReading {
  double linear = 0.0;   ///< m/s, forward
  double angular = 0.0;  ///< rad/s, counter-clockwise
  bool valid = true;     ///< false when the driver flags a drive's actual velocity stale
};

struct EStopSignal {
  bool engaged = false;
  std::string source;
  std::string reason;
};

/// An observed position of an object being pushed (from perception, when it tracks objects).
struct ObjectObservation {
  std::int64_t object_id = -1;
  geometry::Point position = geometry::Point::Zero();
};

struct Inputs {
  std::optional<Stamped<geometry::Pose2>> pose;
  std::optional<Stamped<Path>> path;
  std::optional<Stamped<ForceReading>> force;
  std::optional<Stamped<MotorReading>> motor;
  /// Optional: without it (an old log) motion is judged on the pose alone.
  std::optional<Stamped<OdometryReading>> odometry;
  std::optional<Stamped<EStopSignal>> e_stop;
  std::optional<Stamped<std::vector<geometry::Point>>> obstacles;  ///< world frame, latest local set
  std::optional<Stamped<ObjectObservation>> pushed_object;
};

}  // namespace ifar::executive
