#pragma once
// Motion compensation: each return is placed with the vehicle pose at the return's own time, so a
// scan taken while driving does not smear obstacles.

#include <vector>

#include "common/span.hpp"
#include "common/vehicle.hpp"
#include "planner/perception/sensor_point.hpp"
#include "planner/perception/world_point.hpp"

namespace ifar::perception {

/// The vehicle pose `time_offset_s` after the scan start: linear in position, spherical-linear in
/// rotation. Times outside [0, duration] are clamped to the nearer end pose.
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
