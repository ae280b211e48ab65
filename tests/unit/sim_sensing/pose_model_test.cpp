// The pose model reproduces its configured statistics over long samples: each tolerance is a few
// standard errors of the estimate, tight enough that a model off by a factor (sigma per step instead of
// per sqrt(metre), a variance taken for a sigma) fails.

#include "sim/sensing/pose_model.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"

namespace ifar::sim {
namespace {

constexpr std::int64_t kStepNs = 5'000'000;  // the physics step

struct Moments {
  double mean = 0.0;
  double sigma = 0.0;
};

Moments moments(const std::vector<double>& values)
{
  double sum = 0.0;
  for (const double value : values) {
    sum += value;
  }
  Moments result;
  result.mean = sum / static_cast<double>(values.size());
  double squares = 0.0;
  for (const double value : values) {
    squares += (value - result.mean) * (value - result.mean);
  }
  result.sigma = std::sqrt(squares / static_cast<double>(values.size() - 1));
  return result;
}

/// Drives along +x at `speed` m/s and turns at `turn_rate` rad/s for `steps` physics steps; calls
/// `every(model, step, truth)` after each.
template <typename Visit>
void drive(PoseEstimateModel& model, double speed, double turn_rate, int steps, Visit&& every)
{
  VehicleMotion truth;
  truth.linear_velocity = {speed, 0.0};
  truth.angular_velocity = turn_rate;
  model.advance(truth);
  for (int step = 1; step <= steps; ++step) {
    truth.time_ns += kStepNs;
    truth.pose.x += speed * 0.005;
    truth.pose.heading = geometry::wrapAngle(truth.pose.heading + turn_rate * 0.005);
    model.advance(truth);
    every(model, step, truth);
  }
}

TEST(PoseModel, PositionDriftIsARandomWalkInDistance)
{
  PoseModelSettings settings;
  settings.drift_position_m_per_sqrt_m = 0.05;
  PoseEstimateModel model(settings, 3);
  // 1 m/s: 200 steps per metre; increments of the drift over each metre, along and across.
  std::vector<double> along;
  std::vector<double> across;
  geometry::Pose2 previous;
  drive(model, 1.0, 0.0, 200 * 3000, [&](const PoseEstimateModel& m, int step, const VehicleMotion&) {
    if (step % 200 == 0) {
      const geometry::Pose2 drift = m.drift();
      along.push_back(drift.x - previous.x);
      across.push_back(drift.y - previous.y);
      previous = drift;
    }
  });
  // 3000 samples: the sigma's standard error is 1.3 %, the mean's 0.0009 m.
  const Moments x = moments(along);
  const Moments y = moments(across);
  EXPECT_NEAR(x.sigma, 0.05, 0.05 * 0.05);
  EXPECT_NEAR(y.sigma, 0.05, 0.05 * 0.05);
  EXPECT_NEAR(x.mean, 0.0, 0.004);
  EXPECT_NEAR(y.mean, 0.0, 0.004);
  EXPECT_EQ(model.drift().heading, 0.0);
  // 4 m increments have twice the sigma of 1 m ones (variance grows with distance).
  std::vector<double> four;
  for (std::size_t index = 0; index + 4 <= along.size(); index += 4) {
    four.push_back(along[index] + along[index + 1] + along[index + 2] + along[index + 3]);
  }
  EXPECT_NEAR(moments(four).sigma, 0.1, 0.1 * 0.08);
}

TEST(PoseModel, HeadingDriftGrowsWithDistanceAndWithTurning)
{
  PoseModelSettings per_metre;
  per_metre.drift_heading_rad_per_sqrt_m = 0.01;
  PoseEstimateModel driving(per_metre, 4);
  std::vector<double> increments;
  double previous = 0.0;
  drive(driving, 1.0, 0.0, 200 * 3000, [&](const PoseEstimateModel& m, int step, const VehicleMotion&) {
    if (step % 200 == 0) {
      increments.push_back(m.drift().heading - previous);
      previous = m.drift().heading;
    }
  });
  EXPECT_NEAR(moments(increments).sigma, 0.01, 0.01 * 0.05);
  // A heading error bends the dead-reckoned track: the position drifts across though only the heading
  // is noisy.
  EXPECT_GT(std::abs(driving.drift().y), 0.0);

  PoseModelSettings per_radian;
  per_radian.drift_heading_rad_per_sqrt_rad = 0.02;
  PoseEstimateModel turning(per_radian, 5);
  increments.clear();
  previous = 0.0;
  // Turning in place at 1 rad/s: 200 steps per radian.
  drive(turning, 0.0, 1.0, 200 * 3000, [&](const PoseEstimateModel& m, int step, const VehicleMotion&) {
    if (step % 200 == 0) {
      increments.push_back(m.drift().heading - previous);
      previous = m.drift().heading;
    }
  });
  EXPECT_NEAR(moments(increments).sigma, 0.02, 0.02 * 0.05);
  EXPECT_EQ(turning.drift().x, 0.0);
}

TEST(PoseModel, StandingStillDoesNotDrift)
{
  PoseEstimateModel model(sensingProfile(SensingProfile::kField).pose, 6);
  drive(model, 0.0, 0.0, 20'000, [](const PoseEstimateModel&, int, const VehicleMotion&) {});
  EXPECT_EQ(model.drift().x, 0.0);
  EXPECT_EQ(model.drift().y, 0.0);
  EXPECT_EQ(model.drift().heading, 0.0);
}

TEST(PoseModel, CorrectionsComeAtTheirRateAndRemoveTheirShareOfTheDrift)
{
  PoseModelSettings settings;
  settings.drift_position_m_per_sqrt_m = 0.05;
  settings.drift_heading_rad_per_sqrt_m = 0.005;
  settings.correction_interval_s = 2.0;
  settings.correction_fraction = 0.8;
  PoseEstimateModel model(settings, 7);
  geometry::Pose2 before;
  double kept_dot = 0.0;
  double before_dot = 0.0;
  std::int64_t seen = 0;
  // 4000 s at 1 m/s: about 2000 corrections (Poisson: sigma 45, 2.2 %).
  drive(model, 1.0, 0.0, 200 * 4000, [&](const PoseEstimateModel& m, int, const VehicleMotion&) {
    const geometry::Pose2 now = m.drift();
    if (m.corrections() > seen) {
      seen = m.corrections();
      kept_dot += now.x * before.x + now.y * before.y;
      before_dot += before.x * before.x + before.y * before.y;
    }
    before = now;
  });
  EXPECT_NEAR(static_cast<double>(model.corrections()), 2000.0, 150.0);
  // What stays after a correction is 1 - 0.8 of the drift just before it (one step's noise aside).
  EXPECT_NEAR(kept_dot / before_dot, 0.2, 0.02);
}

TEST(PoseModel, PublishesTheEstimateOfLatencyAgoStampedWithItsTime)
{
  PoseModelSettings settings;
  settings.latency_s = 0.05;
  PoseEstimateModel model(settings, 8);
  std::vector<VehicleMotion> truths;
  drive(model, 0.7, 0.3, 400, [&](const PoseEstimateModel& m, int step, const VehicleMotion&) {
    const VehicleMotion published = m.published();
    if (step >= 10) {
      EXPECT_EQ(published.time_ns, static_cast<std::int64_t>(step - 10) * kStepNs);
      EXPECT_NEAR(published.pose.x, 0.7 * 0.005 * (step - 10), 1e-12);
    } else {
      EXPECT_EQ(published.time_ns, 0);  // nothing older yet: the first estimate
    }
  });
}

TEST(PoseModel, JitterHasItsSigmaAndFollowsTheSeed)
{
  PoseModelSettings settings;
  settings.jitter_position_m = 0.02;
  settings.jitter_heading_rad = 0.004;
  PoseEstimateModel model(settings, 9);
  PoseEstimateModel same(settings, 9);
  PoseEstimateModel other(settings, 10);
  std::vector<double> xs;
  std::vector<double> headings;
  for (int draw = 0; draw < 20'000; ++draw) {
    geometry::Pose2 pose;
    geometry::Pose2 again;
    geometry::Pose2 different;
    model.addJitter(pose);
    same.addJitter(again);
    other.addJitter(different);
    ASSERT_EQ(pose.x, again.x);
    ASSERT_EQ(pose.heading, again.heading);
    if (draw == 0) {
      EXPECT_NE(pose.x, different.x);
    }
    xs.push_back(pose.x);
    headings.push_back(pose.heading);
  }
  // 20000 samples: sigma's standard error 0.5 %.
  EXPECT_NEAR(moments(xs).sigma, 0.02, 0.02 * 0.025);
  EXPECT_NEAR(moments(headings).sigma, 0.004, 0.004 * 0.025);
  EXPECT_NEAR(moments(xs).mean, 0.0, 0.0006);
}

TEST(PoseModel, WithoutSettingsTheEstimateIsTheTruth)
{
  PoseEstimateModel model(PoseModelSettings{}, 1);
  drive(model, 0.8, 0.5, 1000, [](const PoseEstimateModel& m, int step, const VehicleMotion& truth) {
    const VehicleMotion published = m.published();
    EXPECT_EQ(published.time_ns, static_cast<std::int64_t>(step) * kStepNs);
    EXPECT_EQ(published.pose.x, truth.pose.x);
    EXPECT_EQ(published.pose.heading, truth.pose.heading);
    EXPECT_EQ(m.drift().x, 0.0);
    EXPECT_EQ(m.drift().heading, 0.0);
  });
}

}  // namespace
}  // namespace ifar::sim
