#include "drivers/motor/velocity_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/vehicle_model.hpp"

namespace ifar::motor {
namespace {

double toward(double current, double target, double step)
{
  return current + std::clamp(target - current, -step, step);
}

std::int32_t wheelUnitsRoundedDown(double rim_value, double wheel_radius_m)
{
  if (!(wheel_radius_m > 0.0) || !std::isfinite(rim_value) || rim_value <= 0.0) {
    return 0;
  }
  const double units = std::floor(rim_value / wheel_radius_m * 1000.0);
  return static_cast<std::int32_t>(
      std::min(units, static_cast<double>(std::numeric_limits<std::int32_t>::max())));
}

}  // namespace

std::optional<BodyVelocity> withinSpeedLimits(BodyVelocity command, const VelocityLimits& limits)
{
  if (!std::isfinite(command.linear) || !std::isfinite(command.angular)) {
    return std::nullopt;
  }
  double scale = 1.0;
  if (std::abs(command.linear) > limits.max_linear) {
    scale = std::min(scale, limits.max_linear / std::abs(command.linear));
  }
  if (std::abs(command.angular) > limits.max_angular) {
    scale = std::min(scale, limits.max_angular / std::abs(command.angular));
  }
  // The clamp catches the last rounding of the product (1e9 * (1 / 1e9) may land a hair above 1).
  return BodyVelocity{std::clamp(command.linear * scale, -limits.max_linear, limits.max_linear),
                      std::clamp(command.angular * scale, -limits.max_angular, limits.max_angular)};
}

BodyVelocity towardWithinAcceleration(BodyVelocity current, BodyVelocity target, double seconds,
                                      const VelocityLimits& limits)
{
  if (!(seconds > 0.0)) {
    return current;
  }
  return BodyVelocity{toward(current.linear, target.linear, limits.max_linear_acceleration * seconds),
                      toward(current.angular, target.angular, limits.max_angular_acceleration * seconds)};
}

std::int32_t wheelVelocityLimit(const VelocityLimits& limits, double wheel_track_m, double wheel_radius_m)
{
  return wheelUnitsRoundedDown(common::rimSpeeds(limits.max_linear, limits.max_angular, wheel_track_m).right,
                               wheel_radius_m);
}

std::int32_t wheelAccelerationLimit(const VelocityLimits& limits, double wheel_track_m, double wheel_radius_m)
{
  // Rim accelerations follow the body's as rim speeds follow its velocity.
  return wheelUnitsRoundedDown(
      common::rimSpeeds(limits.max_linear_acceleration, limits.max_angular_acceleration, wheel_track_m).right,
      wheel_radius_m);
}

}  // namespace ifar::motor
