#pragma once
// The vehicle's physics and kinematics that every component shares: the one copy of gravity and of the
// differential drive's equations. Header only, without the configuration stack (the motor library links
// without YAML).

namespace ifar::common {

/// Standard gravity, m/s^2: the normal load of a mass on flat ground (push forces, traction, friction).
inline constexpr double kGravity = 9.81;

/// The differential drive's kinematics, the one copy every component uses. Rim speeds of the left and right
/// wheels, m/s, positive where the wheel rolls the vehicle forward.
struct RimSpeeds {
  double left = 0.0;
  double right = 0.0;
};

/// The rim speeds for a body velocity (`linear` m/s forward, `angular` rad/s counter-clockwise):
/// left = v - omega * track / 2, right = v + omega * track / 2.
inline RimSpeeds rimSpeeds(double linear, double angular, double wheel_track_m)
{
  const double half_track = wheel_track_m / 2.0;
  return {linear - angular * half_track, linear + angular * half_track};
}

/// The body velocity (linear m/s, angular rad/s) of wheels turning at `left` and `right` (rad/s, or m/s at
/// the rim with `wheel_radius_m` 1): linear = r (right + left) / 2, angular = r (right - left) / track.
struct BodyVelocity {
  double linear = 0.0;
  double angular = 0.0;
};
inline BodyVelocity bodyVelocity(double left, double right, double wheel_radius_m, double wheel_track_m)
{
  return {wheel_radius_m * (right + left) / 2.0, wheel_radius_m * (right - left) / wheel_track_m};
}

}  // namespace ifar::common
