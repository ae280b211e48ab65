#include "planner/perception/motion_compensation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ifar::perception {

Eigen::Isometry3d interpolateVehiclePose(const ScanMotion& motion, double time_offset_s)
{
  if (!(motion.duration_s > 0.0)) {
    return motion.vehicle_at_end;
  }
  const double fraction = std::clamp(time_offset_s / motion.duration_s, 0.0, 1.0);
  const Eigen::Quaterniond start_rotation(motion.vehicle_at_start.rotation());
  const Eigen::Quaterniond end_rotation(motion.vehicle_at_end.rotation());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = start_rotation.slerp(fraction, end_rotation).toRotationMatrix();
  pose.translation() = (1.0 - fraction) * motion.vehicle_at_start.translation() +
                       fraction * motion.vehicle_at_end.translation();
  return pose;
}

SensorMount lidarMount(const common::VehicleSettings& vehicle)
{
  SensorMount mount = SensorMount::Identity();
  mount.translation() = Eigen::Vector3d(vehicle.lidar_x_m, 0.0, vehicle.lidar_height_m);
  return mount;
}

bool isValidMotion(const ScanMotion& motion)
{
  const auto valid_pose = [](const Eigen::Isometry3d& pose) {
    return pose.matrix().allFinite() && std::abs(pose.linear().determinant() - 1.0) < 1e-6;
  };
  return valid_pose(motion.vehicle_at_start) && valid_pose(motion.vehicle_at_end) &&
         std::isfinite(motion.duration_s) && motion.duration_s >= 0.0;
}

std::vector<WorldPoint> compensateMotion(common::Span<const SensorPoint> points, const SensorMount& mount,
                                         const ScanMotion& motion)
{
  std::vector<WorldPoint> output;
  output.reserve(points.size());
  // A VLP-16 fires 16 lasers at one instant: consecutive points often share a time, so the pose is
  // only re-interpolated when the time changes.
  double cached_time = std::numeric_limits<double>::quiet_NaN();
  Eigen::Isometry3d sensor_to_world = Eigen::Isometry3d::Identity();
  double ground_height = 0.0;
  for (const SensorPoint& point : points) {
    WorldPoint placed;
    placed.reflectivity = point.reflectivity;
    const Eigen::Vector3d position_sensor = point.position_sensor.cast<double>();
    placed.range_m = position_sensor.norm();
    if (!std::isfinite(point.time_offset_s) || !position_sensor.allFinite()) {
      placed.position_world.setConstant(std::numeric_limits<double>::quiet_NaN());
      placed.height_above_ground_m = std::numeric_limits<double>::quiet_NaN();
      output.push_back(placed);
      continue;
    }
    if (!(point.time_offset_s == cached_time)) {
      cached_time = point.time_offset_s;
      const Eigen::Isometry3d vehicle = interpolateVehiclePose(motion, point.time_offset_s);
      sensor_to_world = vehicle * mount;
      ground_height = vehicle.translation().z();
    }
    placed.position_world = sensor_to_world * position_sensor;
    placed.sensor_world = sensor_to_world.translation();
    placed.height_above_ground_m = placed.position_world.z() - ground_height;
    output.push_back(placed);
  }
  return output;
}

}  // namespace ifar::perception
