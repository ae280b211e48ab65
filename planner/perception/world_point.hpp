#pragma once
// A lidar return placed in the world frame, with what the later stages need to judge it.

#include <Eigen/Core>

namespace ifar::perception {

struct WorldPoint {
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();  // metres, world frame
  double height_above_ground_m = 0.0;  // above the vehicle base at the point's time (base is on the ground)
  double range_m = 0.0;                // distance from the sensor, metres
  Eigen::Vector3d sensor_world = Eigen::Vector3d::Zero();  // the sensor at the point's time (its ray's start)
  float reflectivity = 0.0F;
};

}  // namespace ifar::perception
