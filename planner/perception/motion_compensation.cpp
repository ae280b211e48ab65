#include "planner/perception/motion_compensation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ifar::perception {

ScanPoseInterpolator::ScanPoseInterpolator(const ScanMotion& motion)
    : motion_(motion),
      start_rotation_(motion.vehicle_at_start.rotation()),
      end_rotation_(motion.vehicle_at_end.rotation())
{
  const double dot = start_rotation_.dot(end_rotation_);
  if (std::abs(dot) < 1.0 - std::numeric_limits<double>::epsilon()) {
    angle_ = std::acos(std::abs(dot));
    sin_angle_ = std::sin(angle_);
  }
  end_sign_ = dot < 0.0 ? -1.0 : 1.0;
}

Eigen::Isometry3d ScanPoseInterpolator::at(double time_offset_s) const
{
  if (!(motion_.duration_s > 0.0)) {
    return motion_.vehicle_at_end;
  }
  const double fraction = std::clamp(time_offset_s / motion_.duration_s, 0.0, 1.0);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double start_scale = 1.0 - fraction;
  double end_scale = fraction;
  if (sin_angle_ > 0.0) {
    start_scale = std::sin((1.0 - fraction) * angle_) / sin_angle_;
    end_scale = std::sin(fraction * angle_) / sin_angle_;
  }
  const Eigen::Quaterniond rotation(start_scale * start_rotation_.coeffs() +
                                    end_sign_ * end_scale * end_rotation_.coeffs());
  pose.linear() = rotation.toRotationMatrix();
  pose.translation() = (1.0 - fraction) * motion_.vehicle_at_start.translation() +
                       fraction * motion_.vehicle_at_end.translation();
  return pose;
}

Eigen::Isometry3d interpolateVehiclePose(const ScanMotion& motion, double time_offset_s)
{
  return ScanPoseInterpolator(motion).at(time_offset_s);
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
  // Consecutive points may share a time (a sensor that fires its lasers at once), so the pose is only
  // re-interpolated when the time changes.
  const ScanPoseInterpolator poses(motion);
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
      const Eigen::Isometry3d vehicle = poses.at(point.time_offset_s);
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
