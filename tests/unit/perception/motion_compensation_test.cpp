#include "planner/perception/motion_compensation.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"

namespace ifar::perception {
namespace {

using ifar::geometry::kPi;

Eigen::Isometry3d planarPose(double x, double y, double yaw)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, 0.0);
  return pose;
}

SensorPoint pointAt(float x, float y, float z, double time_offset_s)
{
  SensorPoint point;
  point.position_sensor = Eigen::Vector3f(x, y, z);
  point.time_offset_s = time_offset_s;
  return point;
}

/// Drives 1 m along x while turning a quarter turn left over 0.1 s.
ScanMotion drivingAndTurning()
{
  ScanMotion motion;
  motion.vehicle_at_start = planarPose(0.0, 0.0, 0.0);
  motion.vehicle_at_end = planarPose(1.0, 0.0, kPi / 2.0);
  motion.duration_s = 0.1;
  return motion;
}

TEST(MotionCompensation, InterpolatesPositionAndHeading)
{
  const Eigen::Isometry3d middle = interpolateVehiclePose(drivingAndTurning(), 0.05);
  EXPECT_NEAR(middle.translation().x(), 0.5, 1e-12);
  EXPECT_NEAR(middle.translation().y(), 0.0, 1e-12);
  const Eigen::Vector3d forward = middle.linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(forward.y(), forward.x()), kPi / 4.0, 1e-12);
}

TEST(MotionCompensation, TheScanInterpolatorIsEigensSlerpWithTheAngleTakenOnce)
{
  // Pairs of rotations: a small turn, a pair whose quaternions point apart (negative dot product: the
  // end is negated to turn the short way), the same
  // rotation twice (linear interpolation), and a general 3-D one.
  const std::vector<std::pair<Eigen::Matrix3d, Eigen::Matrix3d>> pairs = {
      {Eigen::Matrix3d::Identity(), Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitZ()).toRotationMatrix()},
      {Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitX()).toRotationMatrix(),
       Eigen::AngleAxisd(-2.5, Eigen::Vector3d::UnitY()).toRotationMatrix()},
      {Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX()).toRotationMatrix(),
       Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX()).toRotationMatrix()},
      {Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix(),
       Eigen::AngleAxisd(-1.1, Eigen::Vector3d(-2.0, 0.5, 1.0).normalized()).toRotationMatrix()}};
  for (const auto& [start, end] : pairs) {
    ScanMotion motion;
    motion.vehicle_at_start = Eigen::Isometry3d::Identity();
    motion.vehicle_at_start.linear() = start;
    motion.vehicle_at_end = Eigen::Isometry3d::Identity();
    motion.vehicle_at_end.linear() = end;
    motion.vehicle_at_end.translation() = Eigen::Vector3d(1.0, -2.0, 0.5);
    motion.duration_s = 0.1;
    if (&start == &pairs[1].first) {
      ASSERT_LT(Eigen::Quaterniond(start).dot(Eigen::Quaterniond(end)), 0.0);
    }
    const ScanPoseInterpolator poses(motion);
    for (double time = 0.0; time <= 0.1; time += 0.0037) {
      const Eigen::Matrix3d expected =
          Eigen::Quaterniond(start).slerp(time / 0.1, Eigen::Quaterniond(end)).toRotationMatrix();
      EXPECT_LT((poses.at(time).linear() - expected).cwiseAbs().maxCoeff(), 1e-15) << "time " << time;
      EXPECT_LT((poses.at(time).translation() - Eigen::Vector3d(1.0, -2.0, 0.5) * time / 0.1).norm(), 1e-15);
    }
  }
}

TEST(MotionCompensation, ClampsTimesOutsideTheScan)
{
  const ScanMotion motion = drivingAndTurning();
  EXPECT_NEAR(interpolateVehiclePose(motion, -1.0).translation().x(), 0.0, 1e-12);
  EXPECT_NEAR(interpolateVehiclePose(motion, 5.0).translation().x(), 1.0, 1e-12);
  ScanMotion still = motion;
  still.duration_s = 0.0;
  EXPECT_NEAR(interpolateVehiclePose(still, 0.05).translation().x(), 1.0, 1e-12);
}

TEST(MotionCompensation, MovesEachPointByThePoseAtItsTime)
{
  SensorMount mount = SensorMount::Identity();
  mount.translation() = Eigen::Vector3d(0.2, 0.0, 0.8);
  const std::vector<SensorPoint> points = {pointAt(1.0F, 0.0F, 0.0F, 0.0), pointAt(1.0F, 0.0F, 0.0F, 0.05),
                                           pointAt(1.0F, 0.0F, 0.0F, 0.1), pointAt(2.0F, 1.0F, -0.5F, 0.1)};
  const std::vector<WorldPoint> world = compensateMotion(points, mount, drivingAndTurning());
  ASSERT_EQ(world.size(), 4U);
  // Start pose: sensor 0.2 m ahead of the base, the point 1 m further along x.
  EXPECT_NEAR(world[0].position_world.x(), 1.2, 1e-6);
  EXPECT_NEAR(world[0].position_world.y(), 0.0, 1e-6);
  EXPECT_NEAR(world[0].position_world.z(), 0.8, 1e-6);
  EXPECT_NEAR(world[0].height_above_ground_m, 0.8, 1e-6);
  EXPECT_NEAR(world[0].range_m, 1.0, 1e-6);
  // Half way: base at (0.5, 0), heading 45 degrees, the point 1.2 m ahead along that heading.
  EXPECT_NEAR(world[1].position_world.x(), 0.5 + 1.2 * std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(world[1].position_world.y(), 1.2 * std::sqrt(0.5), 1e-6);
  // End: base at (1, 0) facing +y.
  EXPECT_NEAR(world[2].position_world.x(), 1.0, 1e-6);
  EXPECT_NEAR(world[2].position_world.y(), 1.2, 1e-6);
  // Sensor (2, 1, -0.5) at the end pose: forward 2.2 along +y, left 1 along -x, 0.3 m up.
  EXPECT_NEAR(world[3].position_world.x(), 0.0, 1e-6);
  EXPECT_NEAR(world[3].position_world.y(), 2.2, 1e-6);
  EXPECT_NEAR(world[3].height_above_ground_m, 0.3, 1e-6);
}

TEST(MotionCompensation, NonFiniteInputStaysNonFinite)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<SensorPoint> points = {
      pointAt(nan, 0.0F, 0.0F, 0.0), pointAt(1.0F, 0.0F, 0.0F, std::numeric_limits<double>::infinity())};
  const std::vector<WorldPoint> world =
      compensateMotion(points, SensorMount::Identity(), drivingAndTurning());
  ASSERT_EQ(world.size(), 2U);
  EXPECT_FALSE(world[0].position_world.allFinite());
  EXPECT_FALSE(world[1].position_world.allFinite());
}

TEST(MotionCompensation, MountFromVehicleSettings)
{
  common::VehicleSettings vehicle;
  vehicle.lidar_x_m = 0.25;
  vehicle.lidar_height_m = 0.9;
  const SensorMount mount = lidarMount(vehicle);
  EXPECT_EQ(mount.translation(), Eigen::Vector3d(0.25, 0.0, 0.9));
  EXPECT_TRUE(mount.linear().isIdentity());
}

TEST(MotionCompensation, RejectsInvalidMotion)
{
  EXPECT_TRUE(isValidMotion(drivingAndTurning()));
  ScanMotion bad = drivingAndTurning();
  bad.vehicle_at_end.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(isValidMotion(bad));
  bad = drivingAndTurning();
  bad.duration_s = -0.1;
  EXPECT_FALSE(isValidMotion(bad));
  bad = drivingAndTurning();
  bad.vehicle_at_start.linear() *= 2.0;  // not a rotation
  EXPECT_FALSE(isValidMotion(bad));
}

}  // namespace
}  // namespace ifar::perception
