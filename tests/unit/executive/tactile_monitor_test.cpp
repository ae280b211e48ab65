#include "executive/affordance/tactile_monitor.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>

#include <gtest/gtest.h>

namespace ifar::executive {
namespace {

using geometry::Pose2;

constexpr double kMaxPushForce = 549.36;  // 0.7 x 80 kg x 9.81 m/s^2

/// J = 100 N x 2 m / 100 N + 1 m travel = 3 equivalent metres.
PushPlan plan()
{
  PushPlan result;
  result.object_id = 42;
  result.expected_force_n = 100.0;
  result.push_distance_m = 2.0;
  result.travel_m = 1.0;
  result.expected_cost = 3.0;
  result.affordance = 0.4;
  return result;
}

/// Feeds `force_n` at 100 Hz for `seconds` while the vehicle drives forward at `speed`; returns the first
/// event and when it came.
struct Feed {
  std::optional<AffordanceEvent> event;
  std::int64_t event_us = -1;
};

Feed feed(TactileMonitor& monitor, const TactileSettings& settings, double force_n, double speed,
          double seconds, bool in_contact = true)
{
  Feed result;
  const int cycles = static_cast<int>(seconds * 100.0);
  for (int cycle = 0; cycle <= cycles; ++cycle) {
    const std::int64_t now_us = static_cast<std::int64_t>(cycle) * 10'000;
    const Pose2 vehicle{speed * cycle * 0.01, 0.0, 0.0};
    auto event = monitor.update(now_us, force_n, vehicle, std::nullopt, in_contact, settings);
    if (event && !result.event) {
      result.event = event;
      result.event_us = now_us;
    }
  }
  return result;
}

TEST(TactileMonitor, UnpushableAfterConfiguredTimeAtMaximumForceWithoutMotion)
{
  TactileSettings settings;  // 2 s at >= 90 % of the maximum
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  const Feed result = feed(monitor, settings, 530.0, 0.0, 3.0);
  ASSERT_TRUE(result.event.has_value());
  EXPECT_EQ(result.event_us, 2'000'000);  // not one cycle earlier
  EXPECT_FALSE(result.event->pushable);
  EXPECT_EQ(result.event->reason, AffordanceReason::NoMotion);
  EXPECT_EQ(result.event->object_id, 42);
  EXPECT_DOUBLE_EQ(result.event->push_force_n, 530.0);
  EXPECT_NEAR(result.event->affordance, 2.12, 1e-12);  // 0.4 x 530 N / 100 N
  EXPECT_DOUBLE_EQ(result.event->planned_cost, 3.0);
}

/// Slides the object 1 m at `sliding_force_n` (0.25 m/s), then holds it at 530 N, no motion, for 3 s:
/// the first event after the slide and when it came (microseconds since the start).
Feed slideThenStick(TactileMonitor& monitor, const TactileSettings& settings, double sliding_force_n)
{
  Feed result;
  for (int cycle = 0; cycle <= 700; ++cycle) {  // 4 s sliding, then 3 s stuck, at 100 Hz
    const bool sliding = cycle <= 400;
    const double x = 0.0025 * std::min(cycle, 400);
    const std::int64_t now_us = static_cast<std::int64_t>(cycle) * 10'000;
    auto event = monitor.update(now_us, sliding ? sliding_force_n : 530.0, Pose2{x, 0.0, 0.0}, std::nullopt,
                                true, settings);
    if (event && !result.event && !sliding) {
      result.event = event;
      result.event_us = now_us;
    }
  }
  return result;
}

TEST(TactileMonitor, AnObjectThatSlidThenStopsAtMaximumForceIsJammedNotUnpushable)
{
  TactileSettings settings;  // 2 s at >= 90 % of the maximum; slid >= 0.3 m first
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  const Feed result = slideThenStick(monitor, settings, 100.0);
  ASSERT_TRUE(result.event.has_value());
  EXPECT_EQ(result.event_us, 6'010'000);  // 2 s after the first cycle at 530 N (4.01 s)
  EXPECT_EQ(result.event->reason, AffordanceReason::Jammed);
  EXPECT_TRUE(result.event->pushable);
  // The force it slid at, not the 530 N it was held at: 1 m at 100 N (the 530 N cycles add no travel).
  EXPECT_NEAR(result.event->push_force_n, 100.0, 1e-9);
  EXPECT_NEAR(result.event->affordance, 0.4, 1e-9);
  EXPECT_NEAR(result.event->measured_cost, 3.0, 1e-9);
}

TEST(TactileMonitor, ASecondJamOfTheSameObjectIsUnpushable)
{
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce, /*jammed_before=*/true);
  const Feed result = slideThenStick(monitor, settings, 100.0);
  ASSERT_TRUE(result.event.has_value());
  EXPECT_EQ(result.event->reason, AffordanceReason::NoMotion);
  EXPECT_FALSE(result.event->pushable);
}

TEST(TactileMonitor, AnObjectThatOnlySlidAtMaximumForceIsUnpushableWhenItStops)
{
  TactileSettings settings;
  settings.cost_threshold = 1000.0;  // only the no-motion rule here
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  // 500 N is at the maximum (>= 0.9 x 549 N): the object was as heavy as the vehicle can push all along.
  const Feed result = slideThenStick(monitor, settings, 500.0);
  ASSERT_TRUE(result.event.has_value());
  EXPECT_EQ(result.event->reason, AffordanceReason::NoMotion);
  EXPECT_FALSE(result.event->pushable);
}

TEST(TactileMonitor, ObjectThatMovesAtMaximumForceIsNotUnpushable)
{
  TactileSettings settings;
  settings.cost_threshold = 1000.0;  // only the no-motion rule here
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  EXPECT_FALSE(feed(monitor, settings, 530.0, 0.2, 5.0).event.has_value());
}

TEST(TactileMonitor, ObservedObjectThatMovesWithTheVehicleIsNotUnpushable)
{
  TactileSettings settings;
  settings.cost_threshold = 1000.0;  // only the no-motion rule here
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  for (int cycle = 0; cycle <= 500; ++cycle) {
    const double travelled = 0.001 * cycle;  // 0.1 m/s, object and bumper together
    const auto event = monitor.update(cycle * 10'000, 530.0, {travelled, 0.0, 0.0},
                                      geometry::Point(0.6 + travelled, 0.0), true, settings);
    ASSERT_FALSE(event.has_value()) << "cycle " << cycle;
  }
}

TEST(TactileMonitor, ObservedCentroidJitterWithoutVehicleTravelIsNoMotion)
{
  // The bumper hides the object's near face: its observed centroid wanders by up to 8 cm although
  // neither it nor the vehicle moves (office world, heavy fire-door box). It must not restart the window.
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  std::optional<AffordanceEvent> event;
  std::int64_t event_us = -1;
  for (int cycle = 0; cycle <= 300 && !event; ++cycle) {
    const double jitter = (cycle % 7) * 0.013;  // 0 .. 0.078 m, above the 0.05 m threshold
    const geometry::Point object(0.6 + jitter, 0.5 * jitter);
    event = monitor.update(cycle * 10'000, 530.0, {0.0, 0.0, 0.0}, object, true, settings);
    event_us = cycle * 10'000;
  }
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->reason, AffordanceReason::NoMotion);
  EXPECT_EQ(event_us, 2'000'000);
}

TEST(TactileMonitor, SpinningWheelsWithAStillObjectAreNoMotion)
{
  // Odometry says the vehicle advances (slipping wheels), the observed object stays: unpushable.
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  std::optional<AffordanceEvent> event;
  for (int cycle = 0; cycle <= 300 && !event; ++cycle) {
    event = monitor.update(cycle * 10'000, 530.0, {0.001 * cycle, 0.0, 0.0}, geometry::Point(0.6, 0.0), true,
                           settings);
  }
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->reason, AffordanceReason::NoMotion);
}

TEST(TactileMonitor, BelowMaximumForceNeverUnpushable)
{
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  EXPECT_FALSE(feed(monitor, settings, 450.0, 0.0, 5.0).event.has_value());
}

TEST(TactileMonitor, HigherCostThanPlannedIsReported)
{
  TactileSettings settings;  // threshold 1.0, trusted after 0.3 m
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  const Feed result = feed(monitor, settings, 300.0, 0.3, 3.0);
  ASSERT_TRUE(result.event.has_value());
  EXPECT_TRUE(result.event->pushable);
  EXPECT_EQ(result.event->reason, AffordanceReason::CostHigher);
  // Mean force 300 N: J = 1 + 2 x 300 / 100 = 7.
  EXPECT_NEAR(result.event->measured_cost, 7.0, 1e-9);
  EXPECT_NEAR(result.event->push_force_n, 300.0, 1e-9);
  EXPECT_NEAR(result.event->affordance, 1.2, 1e-9);
  EXPECT_NEAR(static_cast<double>(result.event_us), 1.0e6, 1e4 + 1);  // 0.3 m at 0.3 m/s
}

TEST(TactileMonitor, LowerCostThanPlannedIsReported)
{
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  const Feed result = feed(monitor, settings, 40.0, 0.3, 3.0);
  ASSERT_TRUE(result.event.has_value());
  EXPECT_EQ(result.event->reason, AffordanceReason::CostLower);
  EXPECT_NEAR(result.event->measured_cost, 1.8, 1e-9);  // 1 + 2 x 0.4
}

TEST(TactileMonitor, CostWithinThresholdIsQuiet)
{
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  EXPECT_FALSE(feed(monitor, settings, 120.0, 0.3, 3.0).event.has_value());  // J = 3.4
  EXPECT_NEAR(monitor.extrapolatedCost(), 3.4, 1e-9);
}

TEST(TactileMonitor, NothingMeasuredOutOfContact)
{
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  EXPECT_FALSE(feed(monitor, settings, 530.0, 0.0, 5.0, false).event.has_value());
  EXPECT_DOUBLE_EQ(monitor.measuredDistance(), 0.0);
}

}  // namespace
}  // namespace ifar::executive
