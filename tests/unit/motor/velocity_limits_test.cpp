#include "drivers/motor/velocity_limits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ifar::motor {
namespace {

const VelocityLimits kVehicle{1.0, 1.2, 1.0, 2.0};  // config/vehicle.yaml

TEST(VelocityLimits, ScalesBothSpeedsByOneFactorKeepingTheCurvature)
{
  const auto fast = withinSpeedLimits({1e9, 0.0}, kVehicle);
  ASSERT_TRUE(fast);
  EXPECT_EQ(fast->linear, 1.0);
  EXPECT_EQ(fast->angular, 0.0);
  const auto reverse = withinSpeedLimits({-5.0, 0.0}, kVehicle);
  EXPECT_EQ(reverse->linear, -1.0);
  // 0.5 m/s on a 0.1 m radius asks 5 rad/s: both scaled by 1.2 / 5, the radius stays 0.1 m.
  const auto tight = withinSpeedLimits({0.5, 5.0}, kVehicle);
  EXPECT_DOUBLE_EQ(tight->angular, 1.2);
  EXPECT_DOUBLE_EQ(tight->linear, 0.12);
  const auto within = withinSpeedLimits({0.3, -0.4}, kVehicle);
  EXPECT_EQ(within->linear, 0.3);
  EXPECT_EQ(within->angular, -0.4);
  const auto huge = withinSpeedLimits({-1e300, 1e300}, kVehicle);  // curvature -1: the linear limit binds
  EXPECT_DOUBLE_EQ(huge->linear, -1.0);
  EXPECT_DOUBLE_EQ(huge->angular, 1.0);
}

TEST(VelocityLimits, RefusesWhatIsNotANumber)
{
  EXPECT_FALSE(withinSpeedLimits({std::nan(""), 0.0}, kVehicle));
  EXPECT_FALSE(withinSpeedLimits({0.0, std::numeric_limits<double>::infinity()}, kVehicle));
  EXPECT_FALSE(withinSpeedLimits({-std::numeric_limits<double>::infinity(), 0.0}, kVehicle));
}

TEST(VelocityLimits, AccelerationSteps)
{
  const BodyVelocity step = towardWithinAcceleration({0.0, 0.0}, {1.0, -1.2}, 0.01, kVehicle);
  EXPECT_DOUBLE_EQ(step.linear, 0.01);
  EXPECT_DOUBLE_EQ(step.angular, -0.02);
  const BodyVelocity braking = towardWithinAcceleration({0.8, 0.0}, {0.0, 0.0}, 0.1, kVehicle);
  EXPECT_DOUBLE_EQ(braking.linear, 0.7);
  const BodyVelocity arrived = towardWithinAcceleration({0.995, 0.0}, {1.0, 0.0}, 0.01, kVehicle);
  EXPECT_EQ(arrived.linear, 1.0);
  EXPECT_EQ(towardWithinAcceleration({0.5, 0.1}, {1.0, 0.0}, -1.0, kVehicle).linear, 0.5);
}

TEST(VelocityLimits, WheelLimitsFromTheVehicle)
{
  // (1.0 + 1.2 x 0.3) / 0.15 = 9.0667 rad/s; (1.0 + 2.0 x 0.3) / 0.15 = 10.667 rad/s^2.
  EXPECT_EQ(wheelVelocityLimit(kVehicle, 0.6, 0.15), 9066);
  EXPECT_EQ(wheelAccelerationLimit(kVehicle, 0.6, 0.15), 10666);
  EXPECT_EQ(wheelVelocityLimit(kVehicle, 0.6, 0.0), 0);
}

}  // namespace
}  // namespace ifar::motor
