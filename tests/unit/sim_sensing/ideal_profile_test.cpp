// The ideal profile is the simulator as it was before the sensing models: the fingerprints below were
// taken from that simulator on the same run (pose noise set by the old keys, which are now the pose
// model's jitter), so any change to what the ideal profile sends fails here.

#include <gtest/gtest.h>

#include "sensing_run.hpp"
#include "sim/simulator/builtin_worlds.hpp"

namespace ifar::sim::testing {
namespace {

TEST(IdealProfile, SendsTheBytesOfTheSimulatorBeforeSensingModels)
{
  const auto config = common::ConfigNode::loadString(
      "seed: 5\npose:\n  noise_position_m: 0.02\n  noise_heading_rad: 0.01\n", "sim.yaml");
  const SimNodeSettings settings = loadSimNodeSettings(config);
  ASSERT_EQ(settings.simulator.sensing.profile, SensingProfile::kIdeal);
  // 6 s: drive 0.5 m/s into a 60 kg box, push it, then turn while pushing.
  const RunBytes run = runNode(builtinPushRoom(60.0), settings, 1200, 0.5, 0.4);
  EXPECT_GT(run.outputs.back().objects.at(0).pose.x - run.outputs.front().objects.at(0).pose.x, 1.0);
  EXPECT_EQ(run.packets.size(), 5452326u);
  EXPECT_EQ(fingerprint(run.packets), 5335803635562433284ULL);
  EXPECT_EQ(run.frames.size(), 24960u);
  EXPECT_EQ(fingerprint(run.frames), 16262361668022283970ULL);
  EXPECT_EQ(run.poses.size(), 36120u);
  EXPECT_EQ(fingerprint(run.poses), 17613307599944701991ULL);
}

TEST(IdealProfile, IsTheDefaultAndEverySensingModelIsOff)
{
  const SensingSettings ideal = sensingProfile("ideal");
  EXPECT_EQ(ideal.profile, SensingProfile::kIdeal);
  EXPECT_FALSE(ideal.pose.drifts());
  EXPECT_EQ(ideal.pose.latency_s, 0.0);
  EXPECT_FALSE(ideal.lidar.active());
  EXPECT_EQ(ideal.wheels.slip_ratio_scale, 0.0);
  EXPECT_EQ(ideal.wheels.encoder_counts_per_rev, 0);
  EXPECT_EQ(ideal.force.noise_n, 0.0);
  EXPECT_EQ(SimulatorSettings{}.sensing.profile, SensingProfile::kIdeal);
  const auto shipped = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/sim.yaml");
  EXPECT_EQ(loadSimNodeSettings(shipped).simulator.sensing.profile, SensingProfile::kIdeal);
}

}  // namespace
}  // namespace ifar::sim::testing
