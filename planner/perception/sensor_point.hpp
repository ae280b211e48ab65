#pragma once
// Input of the perception pipeline: returns in the sensor frame with their time within the scan, and
// where the sensor was while they were taken. Independent of the Velodyne decoder's own types.

#include <Eigen/Geometry>

namespace ifar::perception {

/// One lidar return in the sensor frame (x forward, y left, z up).
struct SensorPoint {
  Eigen::Vector3f position_sensor = Eigen::Vector3f::Zero();  // metres
  float reflectivity = 0.0F;                                  // calibrated reflectivity, 0..255
  double time_offset_s = 0.0;                                 // seconds after ScanMotion::start
};

/// The vehicle's motion over one scan: base pose in the world frame (z up, base origin on the ground)
/// at the scan's start and end. Points are placed with the pose interpolated at their own time.
struct ScanMotion {
  Eigen::Isometry3d vehicle_at_start = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d vehicle_at_end = Eigen::Isometry3d::Identity();
  double duration_s = 0.1;  // time from start to end pose; 0 means the vehicle stood still
};

/// The sensor's pose on the vehicle: maps sensor-frame points into the vehicle base frame.
using SensorMount = Eigen::Isometry3d;

}  // namespace ifar::perception
