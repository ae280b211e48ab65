#pragma once
// Differential-drive kinematics and the vehicle's speed and acceleration limits (config/vehicle.yaml).

#include "common/vehicle.hpp"
#include "executive/kinematics/velocity_command.hpp"

namespace ifar::executive {

class DifferentialDrive {
 public:
  /// Copies what it needs from `vehicle`; wheel track and radius must be positive.
  explicit DifferentialDrive(const common::VehicleSettings& vehicle);

  /// left = (v - omega * track / 2) / radius, right = (v + omega * track / 2) / radius.
  WheelSpeeds toWheelSpeeds(const VelocityCommand& command) const;
  VelocityCommand fromWheelSpeeds(const WheelSpeeds& wheels) const;

  /// Scales v and omega down by one common factor (so the arc's curvature is kept) until the linear
  /// speed, the angular speed and both wheel speeds are within the limits. A wheel may turn no faster
  /// than it does at the vehicle's top linear speed. Non-finite input gives a zero command.
  VelocityCommand limitSpeed(const VelocityCommand& command) const;

  /// Limits the change from `previous` over `elapsed_s` seconds by the acceleration limits. Only growth of
  /// a speed's magnitude (and a change of sign) is limited: slowing down toward zero passes unchanged,
  /// because stopping fast is always the safe direction and the drive ramps down by itself.
  VelocityCommand limitAcceleration(const VelocityCommand& desired, const VelocityCommand& previous,
                                    double elapsed_s) const;

  /// limitSpeed, then limitAcceleration.
  VelocityCommand limit(const VelocityCommand& desired, const VelocityCommand& previous,
                        double elapsed_s) const;

  double maxLinearVelocity() const { return max_linear_; }
  double maxAngularVelocity() const { return max_angular_; }
  double maxWheelSpeed() const { return max_wheel_; }

 private:
  double half_track_;
  double wheel_radius_;
  double max_linear_;
  double max_angular_;
  double max_linear_acceleration_;
  double max_angular_acceleration_;
  double max_wheel_;
};

}  // namespace ifar::executive
