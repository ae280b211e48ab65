// The wheel encoder and the force sensor model reproduce their configured statistics, and the force
// driver's monitor still sees what the sensor's errors do to the frames (stuck counter, lost frames).

#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/force_sensor/force_monitor.hpp"
#include "sim/can_nodes/vehicle_can_nodes.hpp"
#include "sim/sensing/force_model.hpp"
#include "sim/sensing/wheel_encoder.hpp"

namespace ifar::sim {
namespace {

TEST(WheelEncoder, QuantisesTheSpeedToEdgesPerWindowAndAveragesToIt)
{
  WheelModelSettings settings;
  settings.encoder_counts_per_rev = 4096;
  settings.velocity_window_s = 0.01;
  WheelEncoder encoder(settings, 0.15);
  const double step = 2.0 * M_PI / 4096.0 / 0.01 * 0.15;  // one edge per window, as rim speed: 2.3 cm/s
  std::map<long, int> levels;
  double sum = 0.0;
  int count = 0;
  for (std::int64_t now_us = 0; now_us <= 100'000'000; now_us += 5'000) {
    const double measured = encoder.measure(now_us, 0.5);
    if (now_us >= 20'000) {
      ++levels[std::lround(measured / step)];
      EXPECT_NEAR(measured / step, std::round(measured / step), 1e-6);
      sum += measured;
      ++count;
    }
  }
  // Two neighbouring levels around 0.5 m/s (21.7 edges per window), averaging to it.
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels.begin()->first, 21);
  EXPECT_NEAR(sum / count, 0.5, 1e-4);
  WheelEncoder exact(WheelModelSettings{}, 0.15);
  EXPECT_EQ(exact.measure(0, 0.4321), 0.4321);
  EXPECT_EQ(exact.measure(5'000, -0.1234), -0.1234);
}

TEST(ForceModel, NoiseHasItsSigmaAroundTheTrueForce)
{
  ForceModelSettings settings;
  settings.noise_n = 2.0;
  ForceSensorModel model(settings, 1);
  double sum = 0.0;
  double squares = 0.0;
  constexpr int kFrames = 100'000;
  for (int frame = 0; frame < kFrames; ++frame) {
    const ForceModelReading reading = model.next(frame * 10'000LL, 100.0);
    ASSERT_TRUE(reading.send);
    sum += reading.force_n - 100.0;
    squares += (reading.force_n - 100.0) * (reading.force_n - 100.0);
  }
  const double mean = sum / kFrames;
  EXPECT_NEAR(mean, 0.0, 0.03);  // 5 standard errors
  EXPECT_NEAR(std::sqrt(squares / kFrames - mean * mean), 2.0, 2.0 * 0.015);
}

TEST(ForceModel, TheZeroWandersWithItsSigmaAndCorrelationTime)
{
  ForceModelSettings settings;
  settings.bias_sigma_n = 3.0;
  settings.bias_time_s = 1.0;
  ForceSensorModel model(settings, 2);
  // 10000 s of frames at 100 Hz: 10000 correlation times.
  std::vector<double> biases;
  for (std::int64_t frame = 0; frame < 1'000'000; ++frame) {
    biases.push_back(model.next(frame * 10'000, 50.0).force_n - 50.0);
  }
  double squares = 0.0;
  double lagged = 0.0;
  for (std::size_t index = 0; index + 100 < biases.size(); ++index) {
    squares += biases[index] * biases[index];
    lagged += biases[index] * biases[index + 100];  // 1 s apart
  }
  EXPECT_NEAR(std::sqrt(squares / static_cast<double>(biases.size() - 100)), 3.0, 3.0 * 0.06);
  EXPECT_NEAR(lagged / squares, std::exp(-1.0), 0.05);
  EXPECT_EQ(biases.front(), 0.0);  // tared at start-up
}

TEST(ForceModel, StuckEpisodesAndLostFramesComeAtTheirRates)
{
  ForceModelSettings settings;
  settings.noise_n = 1.0;
  settings.stuck_interval_s = 1.0;
  settings.stuck_duration_s = 0.1;
  settings.drop_rate = 0.01;
  ForceSensorModel model(settings, 3);
  int episodes = 0;
  int lost = 0;
  int sent = 0;
  bool stuck = false;
  double held = 0.0;
  for (std::int64_t frame = 0; frame < 1'000'000; ++frame) {
    const ForceModelReading reading = model.next(frame * 10'000, 10.0);
    if (reading.stuck && !stuck) {
      ++episodes;
      held = reading.force_n;
    }
    if (reading.stuck) {
      ASSERT_EQ(reading.force_n, held);  // the same frame, repeated
      ASSERT_TRUE(reading.send);
    } else {
      lost += reading.send ? 0 : 1;
      sent += reading.send ? 1 : 0;
    }
    stuck = reading.stuck;
  }
  // 10000 s, an episode every 1 s of healthy time plus its 0.1 s: about 9100 (sigma about 95).
  EXPECT_NEAR(episodes, 10'000.0 / 1.1, 400.0);
  const double lost_share = static_cast<double>(lost) / (lost + sent);
  EXPECT_NEAR(lost_share, 0.01, 0.001);
}

TEST(ForceModel, TheDriversMonitorFlagsTheStuckCounterAndCountsTheLostFrames)
{
  CanNodeSettings settings;
  settings.force.stuck_interval_s = 0.5;
  settings.force.stuck_duration_s = 0.1;
  settings.force.drop_rate = 0.02;
  settings.seed = 4;
  VehicleCanNodes nodes(settings);
  force_sensor::ForceMonitor monitor;
  int stuck_frames = 0;
  int accepted = 0;
  int episodes = 0;
  bool was_stuck = false;
  for (std::int64_t now_us = 0; now_us < 100'000'000; now_us += 5'000) {
    for (const auto& frame : nodes.update(now_us, 40.0, {})) {
      if (monitor.onFrame(frame, now_us) == force_sensor::FrameVerdict::kAccepted) {
        ++accepted;
        const bool stuck = (monitor.sample(now_us).status & force_sensor::kHealthCounterStuck) != 0;
        stuck_frames += stuck ? 1 : 0;
        episodes += stuck && !was_stuck ? 1 : 0;
        was_stuck = stuck;
      }
    }
  }
  // 100 s: about 100 / 0.6 = 167 episodes of 10 frames, each flagged from its third frame on.
  EXPECT_NEAR(episodes, 167, 40);
  EXPECT_NEAR(stuck_frames, episodes * 8, episodes);
  const auto sample = monitor.sample(100'000'000);
  // The frames lost on the bus show as counter gaps: 2 % of the healthy frames.
  EXPECT_NEAR(static_cast<double>(sample.frames_lost) / (accepted + sample.frames_lost), 0.02 * 0.83, 0.005);
}

}  // namespace
}  // namespace ifar::sim
