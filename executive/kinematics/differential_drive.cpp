#include "executive/kinematics/differential_drive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ifar::executive {
namespace {

/// Moves `previous` toward `desired` by at most `max_step` when the magnitude grows or the sign flips.
double limitGrowth(double desired, double previous, double max_step)
{
  const bool same_direction = desired * previous >= 0.0;
  if (same_direction && std::abs(desired) <= std::abs(previous)) {
    return desired;
  }
  if (!same_direction) {
    // Crossing zero: first come down to zero (unlimited), then grow from zero (limited).
    previous = 0.0;
  }
  return std::clamp(desired, previous - max_step, previous + max_step);
}

}  // namespace

DifferentialDrive::DifferentialDrive(const common::VehicleSettings& vehicle)
    : half_track_(vehicle.wheel_track_m / 2.0),
      wheel_radius_(vehicle.wheel_radius_m),
      max_linear_(vehicle.max_linear_velocity),
      max_angular_(vehicle.max_angular_velocity),
      max_linear_acceleration_(vehicle.max_linear_acceleration),
      max_angular_acceleration_(vehicle.max_angular_acceleration),
      max_wheel_(vehicle.max_linear_velocity / vehicle.wheel_radius_m)
{
  if (!(vehicle.wheel_track_m > 0.0) || !(vehicle.wheel_radius_m > 0.0)) {
    throw std::invalid_argument("DifferentialDrive: wheel_track_m and wheel_radius_m must be positive");
  }
}

WheelSpeeds DifferentialDrive::toWheelSpeeds(const VelocityCommand& command) const
{
  const common::RimSpeeds rims = common::rimSpeeds(command.linear, command.angular, 2.0 * half_track_);
  return {rims.left / wheel_radius_, rims.right / wheel_radius_};
}

VelocityCommand DifferentialDrive::fromWheelSpeeds(const WheelSpeeds& wheels) const
{
  const common::BodyVelocity body =
      common::bodyVelocity(wheels.left, wheels.right, wheel_radius_, 2.0 * half_track_);
  return {body.linear, body.angular};
}

VelocityCommand DifferentialDrive::limitSpeed(const VelocityCommand& command) const
{
  if (!std::isfinite(command.linear) || !std::isfinite(command.angular)) {
    return {};
  }
  const WheelSpeeds wheels = toWheelSpeeds(command);
  double scale = 1.0;
  const auto shrink = [&scale](double value, double limit) {
    if (std::abs(value) > limit) {
      scale = std::min(scale, limit / std::abs(value));
    }
  };
  shrink(command.linear, max_linear_);
  shrink(command.angular, max_angular_);
  shrink(wheels.left, max_wheel_);
  shrink(wheels.right, max_wheel_);
  return {command.linear * scale, command.angular * scale};
}

VelocityCommand DifferentialDrive::limitAcceleration(const VelocityCommand& desired,
                                                     const VelocityCommand& previous, double elapsed_s) const
{
  const double dt = std::max(0.0, elapsed_s);
  return {limitGrowth(desired.linear, previous.linear, max_linear_acceleration_ * dt),
          limitGrowth(desired.angular, previous.angular, max_angular_acceleration_ * dt)};
}

VelocityCommand DifferentialDrive::limit(const VelocityCommand& desired, const VelocityCommand& previous,
                                         double elapsed_s) const
{
  return limitAcceleration(limitSpeed(desired), previous, elapsed_s);
}

}  // namespace ifar::executive
