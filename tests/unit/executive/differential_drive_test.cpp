#include "executive/kinematics/differential_drive.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace ifar::executive {
namespace {

common::VehicleSettings vehicle()
{
  return common::VehicleSettings{};  // track 0.6 m, radius 0.15 m, 1 m/s, 1.2 rad/s, 1 m/s^2, 2 rad/s^2
}

TEST(DifferentialDrive, StraightAndTurningWheelSpeeds)
{
  const DifferentialDrive drive(vehicle());
  const WheelSpeeds straight = drive.toWheelSpeeds({0.6, 0.0});
  EXPECT_DOUBLE_EQ(straight.left, 4.0);
  EXPECT_DOUBLE_EQ(straight.right, 4.0);
  const WheelSpeeds spin = drive.toWheelSpeeds({0.0, 1.0});
  EXPECT_DOUBLE_EQ(spin.left, -2.0);  // 0.3 m half track / 0.15 m radius
  EXPECT_DOUBLE_EQ(spin.right, 2.0);
}

TEST(DifferentialDrive, WheelSpeedsRoundTrip)
{
  const DifferentialDrive drive(vehicle());
  const VelocityCommand back = drive.fromWheelSpeeds(drive.toWheelSpeeds({0.37, -0.81}));
  EXPECT_NEAR(back.linear, 0.37, 1e-12);
  EXPECT_NEAR(back.angular, -0.81, 1e-12);
}

TEST(DifferentialDrive, SpeedLimitKeepsCurvature)
{
  const DifferentialDrive drive(vehicle());
  const VelocityCommand fast = drive.limitSpeed({2.0, 0.0});
  EXPECT_DOUBLE_EQ(fast.linear, 1.0);
  EXPECT_DOUBLE_EQ(fast.angular, 0.0);

  // Right wheel wants (1 + 1.2 * 0.3) / 0.15 = 9.07 rad/s > 6.67 rad/s (1 m/s at the wheel).
  const VelocityCommand limited = drive.limitSpeed({1.0, 1.2});
  EXPECT_NEAR(limited.angular / limited.linear, 1.2, 1e-12);
  EXPECT_NEAR(drive.toWheelSpeeds(limited).right, drive.maxWheelSpeed(), 1e-9);
  EXPECT_NEAR(limited.linear, 1.0 / 1.36, 1e-9);
}

TEST(DifferentialDrive, NonFiniteCommandBecomesZero)
{
  const DifferentialDrive drive(vehicle());
  const VelocityCommand command = drive.limitSpeed({std::numeric_limits<double>::quiet_NaN(), 0.5});
  EXPECT_TRUE(command.isZero());
}

TEST(DifferentialDrive, AccelerationLimitsGrowthOnly)
{
  const DifferentialDrive drive(vehicle());
  const VelocityCommand ramp = drive.limitAcceleration({1.0, 1.0}, {0.0, 0.0}, 0.1);
  EXPECT_DOUBLE_EQ(ramp.linear, 0.1);   // 1 m/s^2 x 0.1 s
  EXPECT_DOUBLE_EQ(ramp.angular, 0.2);  // 2 rad/s^2 x 0.1 s
  const VelocityCommand stop = drive.limitAcceleration({0.0, 0.0}, {1.0, -1.0}, 0.02);
  EXPECT_TRUE(stop.isZero());
  const VelocityCommand reverse = drive.limitAcceleration({-1.0, 0.0}, {0.5, 0.0}, 0.1);
  EXPECT_DOUBLE_EQ(reverse.linear, -0.1);
}

TEST(DifferentialDrive, RejectsZeroWheelRadius)
{
  common::VehicleSettings broken = vehicle();
  broken.wheel_radius_m = 0.0;
  EXPECT_THROW(DifferentialDrive{broken}, std::invalid_argument);
}

}  // namespace
}  // namespace ifar::executive
