#pragma once
// The drives' actual velocities (TPDO1) as wheel odometry, odometry_t (channel ODOMETRY), for the daemon
// that owns the motor clients. Library ifar_motor_lcm, so ifar_motor stays free of LCM.

#include <cstdint>

#include "drivers/motor/motor_client.hpp"
#include "ifar/odometry_t.hpp"

namespace ifar::motor {

/// Drive velocity units per rad/s at the wheel (0x606C and 0x60FF count 0.001 rad/s).
inline constexpr double kDriveUnitsPerRadianPerSecond = 1000.0;

struct OdometryGeometry {
  double wheel_radius_m = 0.15;
  double wheel_track_m = 0.6;
  /// A drive whose last TPDO1 is older than this is flagged stale: its speed is the last one received.
  std::int64_t feedback_timeout_us = 50'000;
};

/// Odometry at `utime` from the left and right drives' status: each wheel's last actual velocity in rad/s,
/// the body velocity they give (common::bodyVelocity), the age of each drive's last TPDO1 and a stale bit
/// for a drive without one within the timeout.
ifar::odometry_t toOdometryMessage(const MotorStatus& left, const MotorStatus& right, std::int64_t utime,
                                   const OdometryGeometry& geometry);

}  // namespace ifar::motor
