#include "executive/affordance/tactile_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>

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
    const auto event = monitor.update(static_cast<std::int64_t>(cycle) * 10'000, 530.0, {travelled, 0.0, 0.0},
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
    event = monitor.update(static_cast<std::int64_t>(cycle) * 10'000, 530.0, {0.0, 0.0, 0.0}, object, true,
                           settings);
    event_us = static_cast<std::int64_t>(cycle) * 10'000;
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
    event = monitor.update(static_cast<std::int64_t>(cycle) * 10'000, 530.0, {0.001 * cycle, 0.0, 0.0},
                           geometry::Point(0.6, 0.0), true, settings);
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

// A state estimator's pose and slipping wheels (issue: a heavy box pushed at 549 N for ever, its pose
// jitter read as progress). The executive cycles at 50 Hz; the force rises from contact to the maximum.

constexpr double kCycleS = 0.02;
constexpr std::int64_t kCycleUs = 20'000;

/// The truth plus seeded Gaussian jitter, independent per sample: sigma per axis and on the heading.
class JitteryPose {
 public:
  JitteryPose(unsigned seed, double sigma_m, double sigma_rad)
      : random_(seed), position_(0.0, sigma_m), heading_(0.0, sigma_rad)
  {
  }
  Pose2 operator()(const Pose2& truth)
  {
    const double dx = position_(random_);
    const double dy = position_(random_);
    return Pose2{truth.x + dx, truth.y + dy, truth.heading + heading_(random_)};
  }

 private:
  std::mt19937 random_;
  std::normal_distribution<double> position_;
  std::normal_distribution<double> heading_;
};

struct PushRun {
  std::optional<AffordanceEvent> unpushable;  ///< the first NoMotion event
  std::int64_t unpushable_us = -1;
  std::int64_t saturated_from_us = -1;  ///< the first cycle at the maximum force
};

/// `seconds` of a push at 50 Hz: the force rises from 20 N to 540 N (above 90 % of the maximum) over
/// 0.5 s and stays; the vehicle (and the object on its bumper) advances at `vehicle_speed` along x, the
/// wheels roll at `wheel_speed` (none: no odometry, as in an old log).
PushRun push(TactileMonitor& monitor, const TactileSettings& settings, JitteryPose& estimator,
             double vehicle_speed, std::optional<double> wheel_speed, double seconds)
{
  PushRun run;
  const int cycles = static_cast<int>(seconds / kCycleS);
  for (int cycle = 0; cycle <= cycles; ++cycle) {
    const double t = cycle * kCycleS;
    const std::int64_t now_us = cycle * kCycleUs;
    const double force = 20.0 + 520.0 * std::min(1.0, t / 0.5);
    if (run.saturated_from_us < 0 && force >= settings.max_force_fraction * kMaxPushForce) {
      run.saturated_from_us = now_us;
    }
    const Pose2 pose = estimator(Pose2{vehicle_speed * t, 0.0, 0.0});
    const std::optional<double> wheels = wheel_speed ? std::optional<double>(*wheel_speed * t) : std::nullopt;
    const auto event = monitor.update(now_us, force, pose, wheels, std::nullopt, true, settings);
    if (event && event->reason == AffordanceReason::NoMotion && !run.unpushable) {
      run.unpushable = event;
      run.unpushable_us = now_us;
    }
  }
  return run;
}

/// Decided unpushable within the no-motion window after the force reached the maximum (one cycle late at
/// most), for every seed.
void expectUnpushableWithinTheWindow(double wheel_speed_or_nan, const char* what)
{
  TactileSettings settings;          // 2 s at >= 90 % of the maximum, 5 cm motion threshold
  settings.cost_threshold = 1000.0;  // only the no-motion rule here
  const std::optional<double> wheels =
      std::isnan(wheel_speed_or_nan) ? std::nullopt : std::optional<double>(wheel_speed_or_nan);
  for (unsigned seed = 1; seed <= 40; ++seed) {
    JitteryPose estimator(seed, 0.02, 0.003);
    TactileMonitor monitor;
    monitor.begin(plan(), kMaxPushForce);
    const PushRun run = push(monitor, settings, estimator, 0.0, wheels, 4.0);
    ASSERT_TRUE(run.unpushable.has_value()) << what << ", seed " << seed;
    EXPECT_FALSE(run.unpushable->pushable);
    EXPECT_LE(run.unpushable_us - run.saturated_from_us,
              static_cast<std::int64_t>(settings.no_motion_time_s * 1e6) + kCycleUs)
        << what << ", seed " << seed;
  }
}

TEST(TactileMonitor, PoseJitterAgainstAnImmovableObjectIsUnpushableWithinTheWindow)
{
  // No odometry (an old log): the smoothed pose alone decides.
  expectUnpushableWithinTheWindow(std::nan(""), "pose alone");
}

TEST(TactileMonitor, PoseJitterWithStandingWheelsIsUnpushableWithinTheWindow)
{
  expectUnpushableWithinTheWindow(0.0, "standing wheels");
}

TEST(TactileMonitor, WheelSlipUnderPoseJitterIsUnpushableWithinTheWindow)
{
  // The wheels roll on at the push speed against the object; the vehicle stays, its pose jitters.
  expectUnpushableWithinTheWindow(0.3, "slipping wheels");
}

TEST(TactileMonitor, ASlowlyMovingObjectUnderPoseJitterIsNotUnpushable)
{
  TactileSettings settings;
  settings.cost_threshold = 1000.0;  // only the no-motion rule here
  // 5 cm/s at the maximum force: 10 cm per no-motion window. With wheels that agree, with wheels that
  // slip on top of it, and without odometry.
  for (const std::optional<double> wheels :
       {std::optional<double>(0.05), std::optional<double>(0.15), std::optional<double>()}) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
      JitteryPose estimator(seed, 0.02, 0.003);
      TactileMonitor monitor;
      monitor.begin(plan(), kMaxPushForce);
      const PushRun run = push(monitor, settings, estimator, 0.05, wheels, 12.0);
      EXPECT_FALSE(run.unpushable.has_value())
          << "seed " << seed << ", wheels " << (wheels ? *wheels : -1.0) << ": " << run.unpushable->text;
      // 0.05 m/s x 12 s loaded, within the jitter of two samples.
      EXPECT_NEAR(monitor.measuredDistance(), 0.6, 0.1) << "seed " << seed;
    }
  }
}

TEST(TactileMonitor, PoseJitterIsNoDistancePushed)
{
  // Stuck for 6 s below the maximum force: neither the distance nor the cost may grow with the jitter.
  TactileSettings settings;
  TactileMonitor pose_alone;
  TactileMonitor with_wheels;
  pose_alone.begin(plan(), kMaxPushForce);
  with_wheels.begin(plan(), kMaxPushForce);
  JitteryPose estimator(7, 0.02, 0.003);
  std::optional<AffordanceEvent> event;
  for (int cycle = 0; cycle <= 300; ++cycle) {
    const Pose2 pose = estimator(Pose2{1.0, 2.0, 0.0});
    event = event ? event : pose_alone.update(cycle * kCycleUs, 300.0, pose, std::nullopt, true, settings);
    event =
        event ? event : with_wheels.update(cycle * kCycleUs, 300.0, pose, 0.0, std::nullopt, true, settings);
  }
  EXPECT_FALSE(event.has_value()) << event->text;
  EXPECT_LT(pose_alone.measuredDistance(), 0.1);          // the jitter of two samples, not 6 s of it
  EXPECT_DOUBLE_EQ(with_wheels.measuredDistance(), 0.0);  // the wheels stood: nothing was pushed
}

TEST(TactileMonitor, SlippingWheelsOnAMovingObjectCountThePosesTravel)
{
  // The object slides at 0.1 m/s, the wheels roll at 0.3 m/s: the distance pushed is the vehicle's.
  TactileSettings settings;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  for (int cycle = 0; cycle <= 150; ++cycle) {
    const double t = cycle * kCycleS;
    monitor.update(cycle * kCycleUs, 100.0, Pose2{0.1 * t, 0.0, 0.0}, 0.3 * t, std::nullopt, true, settings);
  }
  EXPECT_NEAR(monitor.measuredDistance(), 0.3, 1e-9);
  EXPECT_NEAR(monitor.meanForce(), 100.0, 1e-9);
}

TEST(TactileMonitor, StaleOdometryInTheWindowFallsBackToThePose)
{
  // The wheels' count is lost for a second in the middle of a stuck push under jitter: the pose carries
  // the window, which still ends on time.
  TactileSettings settings;
  settings.cost_threshold = 1000.0;
  TactileMonitor monitor;
  monitor.begin(plan(), kMaxPushForce);
  JitteryPose estimator(3, 0.02, 0.003);
  std::optional<AffordanceEvent> event;
  std::int64_t event_us = -1;
  for (int cycle = 0; cycle <= 200 && !event; ++cycle) {
    const double t = cycle * kCycleS;
    const std::optional<double> wheels = t > 0.5 && t < 1.5 ? std::nullopt : std::optional<double>(0.3 * t);
    event = monitor.update(cycle * kCycleUs, 540.0, estimator(Pose2{}), wheels, std::nullopt, true, settings);
    event_us = cycle * kCycleUs;
  }
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->reason, AffordanceReason::NoMotion);
  EXPECT_EQ(event_us, 2'000'000);
}

}  // namespace
}  // namespace ifar::executive
