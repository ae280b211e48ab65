// The lidar return model reproduces its configured statistics over long samples (tolerances of a few
// standard errors), and the scanner applies it to what it casts.

#include "sim/sensing/lidar_model.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::sim {
namespace {

constexpr int kSamples = 200'000;

TEST(LidarModel, RangeNoiseHasItsSigmaAndNoBias)
{
  LidarModelSettings settings;
  settings.range_noise_m = 0.015;
  LidarReturnModel model(settings, 1);
  double sum = 0.0;
  double squares = 0.0;
  for (int sample = 0; sample < kSamples; ++sample) {
    const LidarReturn out = model.apply(10.0, 0.2, 1.0, false);
    ASSERT_TRUE(out.returned);
    ASSERT_EQ(out.reflectivity, 51);  // untouched: no reflectivity settings
    sum += out.slant_m - 10.0;
    squares += (out.slant_m - 10.0) * (out.slant_m - 10.0);
  }
  const double mean = sum / kSamples;
  const double sigma = std::sqrt(squares / kSamples - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.0002);           // 6 standard errors
  EXPECT_NEAR(sigma, 0.015, 0.015 * 0.01);  // sigma's standard error 0.16 %
}

TEST(LidarModel, DropoutsComeAtTheirRate)
{
  LidarModelSettings settings;
  settings.dropout_rate = 0.01;
  LidarReturnModel model(settings, 2);
  int lost = 0;
  for (int sample = 0; sample < kSamples; ++sample) {
    lost += model.apply(5.0, 0.2, 1.0, false).returned ? 0 : 1;
  }
  // 2000 expected, Poisson sigma 45.
  EXPECT_NEAR(lost, 2000, 200);
}

TEST(LidarModel, DarkAndGrazingSurfacesAreSeenOnlyNearer)
{
  LidarModelSettings settings;
  settings.detection_range_m = 50.0;
  LidarReturnModel model(settings, 3);
  // A 10 % surface head-on reaches 50 m; 40 % reaches twice as far; 40 % at cos 0.25 is back to 50 m.
  EXPECT_TRUE(model.apply(49.9, 0.1, 1.0, false).returned);
  EXPECT_FALSE(model.apply(50.1, 0.1, 1.0, false).returned);
  EXPECT_TRUE(model.apply(99.9, 0.4, 1.0, false).returned);
  EXPECT_FALSE(model.apply(50.1, 0.4, 0.25, false).returned);
  EXPECT_TRUE(model.apply(49.9, 0.4, 0.25, false).returned);
  // A wall (20 %) met nearly edge-on (85 degrees) vanishes beyond about 21 m.
  const double grazing = std::cos(85.0 * M_PI / 180.0);
  EXPECT_TRUE(model.apply(20.0, 0.2, grazing, false).returned);
  EXPECT_FALSE(model.apply(22.0, 0.2, grazing, false).returned);
}

TEST(LidarModel, TagErrorsComeAtTheirRatesOnTheirSurfaces)
{
  LidarModelSettings settings;
  settings.false_tag_rate = 0.01;
  settings.missed_tag_rate = 0.05;
  LidarReturnModel model(settings, 4);
  int false_tags = 0;
  int ground_tags = 0;
  int missed_tags = 0;
  for (int sample = 0; sample < kSamples; ++sample) {
    const LidarReturn wall = model.apply(5.0, 0.2, 1.0, false);
    false_tags += wall.reflectivity >= 101 ? 1 : 0;
    ASSERT_TRUE(wall.reflectivity == 51 || wall.reflectivity == 150);
    ground_tags += model.apply(5.0, 0.08, 0.3, true).reflectivity >= 101 ? 1 : 0;
    const LidarReturn tag = model.apply(5.0, 0.9, 1.0, false);
    missed_tags += tag.reflectivity < 101 ? 1 : 0;
    ASSERT_TRUE(tag.reflectivity == 230 || tag.reflectivity == 60);
  }
  EXPECT_NEAR(false_tags, 2000, 200);    // Poisson sigma 45
  EXPECT_NEAR(missed_tags, 10000, 500);  // binomial sigma 97
  EXPECT_EQ(ground_tags, 0);
}

TEST(LidarModel, ReflectivityNoiseHasItsSigma)
{
  LidarModelSettings settings;
  settings.reflectivity_noise = 3.0;
  LidarReturnModel model(settings, 5);
  double sum = 0.0;
  double squares = 0.0;
  for (int sample = 0; sample < kSamples; ++sample) {
    const double value = model.apply(5.0, 0.2, 1.0, false).reflectivity - 51.0;
    sum += value;
    squares += value * value;
  }
  const double mean = sum / kSamples;
  // Rounding to whole units adds 1/12 to the variance.
  EXPECT_NEAR(std::sqrt(squares / kSamples - mean * mean), std::sqrt(9.0 + 1.0 / 12.0), 0.05);
  EXPECT_NEAR(mean, 0.0, 0.05);
}

TEST(LidarModel, TheScannerCastsTheSameRaysAndAddsTheNoise)
{
  // The vehicle stands still in a 12 m room: both simulators fire the same rays at the same surfaces.
  SimulatorSettings exact;
  SimulatorSettings noisy;
  noisy.sensing.lidar.range_noise_m = 0.02;
  Simulator first(builtinRoom(), common::VehicleSettings{}, exact);
  Simulator second(builtinRoom(), common::VehicleSettings{}, noisy);
  first.recordReturns(true);
  second.recordReturns(true);
  first.step(0.2);
  second.step(0.2);
  const auto truths = first.takeReturns();
  const auto noisies = second.takeReturns();
  ASSERT_EQ(truths.size(), noisies.size());
  double squares = 0.0;
  int count = 0;
  for (std::size_t index = 0; index < truths.size(); ++index) {
    if (truths[index].slant_distance_m > 0.0 && noisies[index].slant_distance_m > 0.0) {
      const double error = noisies[index].slant_distance_m - truths[index].slant_distance_m;
      squares += error * error;
      ++count;
    }
  }
  ASSERT_GT(count, 30'000);
  EXPECT_NEAR(std::sqrt(squares / count), 0.02, 0.02 * 0.03);
}

TEST(LidarModel, TheScannerLosesFarGrazingReturns)
{
  // The room's walls are 20 % reflective: with a 10 m reach for 10 % surfaces head-on, nothing beyond
  // 10 x sqrt(2) = 14.1 m returns, and the returns that remain thin out as the walls turn edge-on.
  SimulatorSettings settings;
  settings.sensing.lidar.detection_range_m = 10.0;
  Simulator simulator(builtinRoom(30.0), common::VehicleSettings{}, settings);
  Simulator exact(builtinRoom(30.0), common::VehicleSettings{}, SimulatorSettings{});
  simulator.recordReturns(true);
  exact.recordReturns(true);
  simulator.step(0.2);
  exact.step(0.2);
  int far_exact = 0;
  for (const auto& hit : exact.takeReturns()) {
    far_exact += hit.slant_distance_m > 14.2 ? 1 : 0;
  }
  int far = 0;
  int wall_returns = 0;
  for (const auto& hit : simulator.takeReturns()) {
    far += hit.slant_distance_m > 14.2 ? 1 : 0;
    wall_returns += hit.surface == lidar::RayHit::Surface::Wall ? 1 : 0;
  }
  EXPECT_GT(far_exact, 1000);
  EXPECT_EQ(far, 0);
  EXPECT_GT(wall_returns, 1000);
}

}  // namespace
}  // namespace ifar::sim
