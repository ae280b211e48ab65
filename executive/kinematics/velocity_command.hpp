#pragma once
// The two ways of saying how a differential-drive vehicle moves: body velocities and wheel speeds.

namespace ifar::executive {

/// Body-frame velocity of the vehicle's reference point.
struct VelocityCommand {
  double linear = 0.0;   ///< m/s, forward positive
  double angular = 0.0;  ///< rad/s, counter-clockwise positive

  bool isZero() const { return linear == 0.0 && angular == 0.0; }
};

/// Wheel angular speeds, rad/s, positive when that wheel drives the vehicle forward.
struct WheelSpeeds {
  double left = 0.0;
  double right = 0.0;
};

}  // namespace ifar::executive
