#pragma once
// Motion compensation: each return is placed with the vehicle pose at the return's own time, so a
// scan taken while driving does not smear obstacles.

#include <vector>

#include "common/span.hpp"
#include "common/vehicle.hpp"
#include "planner/perception/sensor_point.hpp"
#include "planner/perception/world_point.hpp"

namespace ifar::perception {

/// The vehicle poses along one scan's motion: linear in position, spherical-linear in rotation. The end
/// rotations are turned into quaternions once, not for each of a revolution's ~29,000 firing times (a
/// VLP-16's lasers fire 2.3 us apart, so nearly every return has its own time).
class ScanPoseInterpolator {
 public:
  explicit ScanPoseInterpolator(const ScanMotion& motion);
  /// The pose `time_offset_s` after the scan start; times outside [0, duration] are clamped to the nearer
  /// end pose.
  Eigen::Isometry3d at(double time_offset_s) const;

 private:
  ScanMotion motion_;
  Eigen::Quaterniond start_rotation_;
  Eigen::Quaterniond end_rotation_;
  // Eigen's slerp, with the angle between the end rotations taken once: 0 when they are (nearly) equal
  // and the interpolation is linear; the end's sign flipped when that is the shorter way round.
  double angle_ = 0.0;
  double sin_angle_ = 0.0;
  double end_sign_ = 1.0;
};

/// ScanPoseInterpolator(motion).at(time_offset_s), for a single pose.
Eigen::Isometry3d interpolateVehiclePose(const ScanMotion& motion, double time_offset_s);

/// The lidar mount from the vehicle settings: lidar_x_m ahead of the base origin, lidar_height_m up,
/// axes aligned with the vehicle's.
SensorMount lidarMount(const common::VehicleSettings& vehicle);

/// True when both poses and the duration are finite and the rotations are proper (unit determinant).
bool isValidMotion(const ScanMotion& motion);

/// Every input point in the world frame, in input order. Non-finite inputs (position or time) stay
/// non-finite in the output so the height filter counts them.
std::vector<WorldPoint> compensateMotion(common::Span<const SensorPoint> points, const SensorMount& mount,
                                         const ScanMotion& motion);

}  // namespace ifar::perception
