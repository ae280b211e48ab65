// Wheel odometry in the executive: dead reckoning between control cycles, and stand-stills judged where
// pose and wheels agree.

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "executive/modes/odometer.hpp"
#include "executive/modes/standstill_watch.hpp"

namespace ifar::executive {
namespace {

constexpr std::int64_t kCycleUs = 20'000;

TEST(Odometer, DeadReckonsAConstantArc)
{
  Odometer odometer;
  EXPECT_FALSE(odometer.track().has_value());
  const OdometryReading reading{0.5, 0.2, true};
  for (int cycle = 0; cycle <= 100; ++cycle) {  // 2 s
    odometer.update(cycle * kCycleUs, reading);
  }
  ASSERT_TRUE(odometer.track().has_value());
  const WheelTrack track = *odometer.track();
  // The arc of radius v / omega = 2.5 m through 0.4 rad.
  EXPECT_NEAR(track.pose.x, 2.5 * std::sin(0.4), 1e-6);
  EXPECT_NEAR(track.pose.y, 2.5 * (1.0 - std::cos(0.4)), 1e-6);
  EXPECT_NEAR(track.pose.heading, 0.4, 1e-12);
  EXPECT_NEAR(track.travel_m, 1.0, 1e-12);
}

TEST(Odometer, ReversingCountsBackward)
{
  Odometer odometer;
  for (int cycle = 0; cycle <= 50; ++cycle) {
    odometer.update(cycle * kCycleUs, OdometryReading{-0.2, 0.0, true});
  }
  EXPECT_NEAR(odometer.track()->travel_m, -0.2, 1e-12);
  EXPECT_NEAR(odometer.track()->pose.x, -0.2, 1e-12);
}

TEST(Odometer, AGapIsNotIntegratedAndStartsANewSegment)
{
  Odometer odometer;
  odometer.update(0, OdometryReading{1.0, 0.0, true});
  odometer.update(kCycleUs, OdometryReading{1.0, 0.0, true});
  const WheelTrack before = *odometer.track();
  EXPECT_NEAR(before.travel_m, 0.02, 1e-12);
  odometer.update(2 * kCycleUs, std::nullopt);  // stale
  EXPECT_FALSE(odometer.track().has_value());
  odometer.update(50 * kCycleUs, OdometryReading{1.0, 0.0, true});
  const WheelTrack after = *odometer.track();
  EXPECT_NEAR(after.travel_m, 0.02, 1e-12);  // nothing for the second without odometry
  EXPECT_NE(after.segment, before.segment);
  EXPECT_FALSE(wheelMotion(before, after).has_value());
  odometer.update(51 * kCycleUs, OdometryReading{1.0, 0.0, true});
  const std::optional<WheelMotion> motion = wheelMotion(after, *odometer.track());
  ASSERT_TRUE(motion.has_value());
  EXPECT_NEAR(motion->distance_m, 0.02, 1e-12);
  EXPECT_NEAR(motion->travel_m, 0.02, 1e-12);
}

/// The stand-still watch of following (0.1 m, 0.3 rad, 1.5 s), fed at 50 Hz with `pose(t)` and, when
/// `wheel_speed` is set, wheels rolling forward at it; the time it first reports standing still, or -1.
template <typename PoseAt>
double firstStandstill(PoseAt pose, std::optional<double> wheel_speed, double seconds)
{
  StandstillWatch watch(0.1, 0.3, 1.5);
  Odometer odometer;
  for (int cycle = 0; cycle * 0.02 <= seconds; ++cycle) {
    const double t = cycle * 0.02;
    CycleView view;
    view.now_us = cycle * kCycleUs;
    view.pose = pose(t);
    if (wheel_speed) {
      odometer.update(view.now_us, OdometryReading{*wheel_speed, 0.0, true});
      view.wheels = odometer.track();
    }
    if (cycle == 0) {
      watch.anchor(view);
    } else if (watch.standingStill(view)) {
      return t;
    }
  }
  return -1.0;
}

TEST(StandstillWatch, WheelsSlippingOnTheSpotAreStandingStill)
{
  const auto still = [](double) { return geometry::Pose2{3.0, 1.0, 0.5}; };
  EXPECT_NEAR(firstStandstill(still, 0.4, 3.0), 1.52, 1e-9);
}

TEST(StandstillWatch, PoseJitterWithStandingWheelsIsStandingStill)
{
  // 5 cm of jitter per sample often moves the pose 0.1 m from the anchor; the wheels stand.
  std::mt19937 random(11);
  std::normal_distribution<double> jitter(0.0, 0.05);
  const auto jittery = [&](double) { return geometry::Pose2{jitter(random), jitter(random), 0.0}; };
  EXPECT_NEAR(firstStandstill(jittery, 0.0, 3.0), 1.52, 1e-9);
  // The pose alone is fooled by the same jitter (the reason for the wheels).
  std::mt19937 again(11);
  std::normal_distribution<double> same(0.0, 0.05);
  const auto jittery_again = [&](double) { return geometry::Pose2{same(again), same(again), 0.0}; };
  EXPECT_LT(firstStandstill(jittery_again, std::nullopt, 3.0), 0.0);
}

TEST(StandstillWatch, DrivingWithWheelsThatAgreeIsMotion)
{
  const auto driving = [](double t) { return geometry::Pose2{0.3 * t, 0.0, 0.0}; };
  EXPECT_LT(firstStandstill(driving, 0.3, 3.0), 0.0);
  EXPECT_LT(firstStandstill(driving, std::nullopt, 3.0), 0.0);
}

}  // namespace
}  // namespace ifar::executive
