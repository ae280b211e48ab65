#pragma once
// The vehicle's speed and acceleration limits applied to a body velocity command before it becomes
// wheel speeds, and the wheel-level limits that follow from them (what the drives are told at start-up
// and what RPDO1 never exceeds). Pure functions; units SI unless a name says drive units (0.001 rad/s
// at the wheel, 0.001 rad/s^2).

#include <cstdint>
#include <optional>

namespace ifar::motor {

struct VelocityLimits {
  double max_linear = 1.0;                // m/s, either direction
  double max_angular = 1.2;               // rad/s, either direction
  double max_linear_acceleration = 1.0;   // m/s^2, speeding up and slowing down alike
  double max_angular_acceleration = 2.0;  // rad/s^2
};

/// Forward speed (m/s) and yaw rate (rad/s, counter-clockwise positive) of the vehicle.
struct BodyVelocity {
  double linear = 0.0;
  double angular = 0.0;
};

/// `command` scaled down by one factor until both speeds are within the limits, so the vehicle keeps
/// the commanded curvature (the arc it drives) at a lower speed. nullopt when either value is NaN or
/// infinite: such a command means nothing and is refused, not clamped.
std::optional<BodyVelocity> withinSpeedLimits(BodyVelocity command, const VelocityLimits& limits);

/// `current` moved toward `target` by at most max_linear_acceleration x seconds and
/// max_angular_acceleration x seconds; `seconds` <= 0 leaves it where it is.
BodyVelocity towardWithinAcceleration(BodyVelocity current, BodyVelocity target, double seconds,
                                      const VelocityLimits& limits);

/// The fastest either wheel turns within the limits, in drive units, rounded down:
/// (max_linear + max_angular x track / 2) / radius x 1000. 0 for a non-positive radius.
std::int32_t wheelVelocityLimit(const VelocityLimits& limits, double wheel_track_m, double wheel_radius_m);
/// The same for accelerations: (max_linear_acceleration + max_angular_acceleration x track / 2) / radius.
std::int32_t wheelAccelerationLimit(const VelocityLimits& limits, double wheel_track_m,
                                    double wheel_radius_m);

}  // namespace ifar::motor
