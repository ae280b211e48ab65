#include "executive/modes/odometer.hpp"

#include <cmath>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

void Odometer::update(std::int64_t now_us, const std::optional<OdometryReading>& reading)
{
  if (!reading) {
    fresh_ = false;
    return;
  }
  if (!fresh_) {
    ++track_.segment;  // a new segment: the gap is not integrated
  } else if (now_us > last_us_) {
    const double dt = static_cast<double>(now_us - last_us_) * 1e-6;
    const double linear = 0.5 * (last_.linear + reading->linear);
    const double angular = 0.5 * (last_.angular + reading->angular);
    const double heading = track_.pose.heading + 0.5 * angular * dt;  // midpoint of the arc
    track_.pose.x += linear * dt * std::cos(heading);
    track_.pose.y += linear * dt * std::sin(heading);
    track_.pose.heading = wrapToPi(track_.pose.heading + angular * dt);
    track_.travel_m += linear * dt;
  }
  fresh_ = true;
  last_ = *reading;
  last_us_ = now_us;
}

std::optional<WheelTrack> Odometer::track() const
{
  return fresh_ ? std::optional<WheelTrack>(track_) : std::nullopt;
}

std::optional<WheelMotion> wheelMotion(const WheelTrack& from, const WheelTrack& to)
{
  if (from.segment != to.segment) {
    return std::nullopt;
  }
  WheelMotion motion;
  motion.distance_m = (to.pose.position() - from.pose.position()).norm();
  motion.turn_rad = std::abs(wrapToPi(to.pose.heading - from.pose.heading));
  motion.travel_m = to.travel_m - from.travel_m;
  return motion;
}

}  // namespace ifar::executive
