#include <stdexcept>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "sim/node/node_settings.hpp"
#include "sim/sensing/sensing_settings.hpp"

namespace ifar::sim {
namespace {

TEST(SensingProfile, FieldHasEveryModelOn)
{
  const SensingSettings field = sensingProfile("field");
  EXPECT_EQ(field.profile, SensingProfile::kField);
  EXPECT_TRUE(field.pose.drifts());
  EXPECT_GT(field.pose.latency_s, 0.0);
  EXPECT_GT(field.pose.correction_interval_s, 0.0);
  EXPECT_TRUE(field.lidar.active());
  EXPECT_DOUBLE_EQ(field.lidar.range_noise_m, 0.015);
  EXPECT_GT(field.wheels.slip_ratio_scale, 0.0);
  EXPECT_GT(field.wheels.encoder_counts_per_rev, 0);
  EXPECT_GT(field.force.noise_n, 0.0);
  EXPECT_GT(field.force.drop_rate, 0.0);
  EXPECT_EQ(sensingProfileNames(), (std::vector<std::string>{"ideal", "field"}));
}

TEST(SensingProfile, OnlyARandomModelMakesTheSeedMatter)
{
  EXPECT_FALSE(sensingProfile("ideal").drawsRandomNumbers());
  EXPECT_TRUE(sensingProfile("field").drawsRandomNumbers());
  SensingSettings settings = sensingProfile("ideal");
  settings.wheels.encoder_counts_per_rev = 1024;  // quantisation draws nothing
  settings.wheels.slip_ratio_scale = 0.1;
  EXPECT_FALSE(settings.drawsRandomNumbers());
  settings.force.drop_rate = 0.01;
  EXPECT_TRUE(settings.drawsRandomNumbers());
  settings = sensingProfile("ideal");
  settings.pose.correction_interval_s = 5.0;
  EXPECT_TRUE(settings.drawsRandomNumbers());
}

TEST(SensingProfile, AnUnknownNameIsRefusedNamingTheKnownOnes)
{
  try {
    sensingProfile("noisy");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("'noisy'"), std::string::npos) << what;
    EXPECT_NE(what.find("ideal, field"), std::string::npos) << what;
  }
  EXPECT_THROW(parseSensingProfile("Field"), std::invalid_argument);
  EXPECT_EQ(parseSensingProfile("field"), SensingProfile::kField);
}

TEST(SensingConfig, TheProfileGivesTheDefaultsAndKeysOverrideThem)
{
  const auto root = common::ConfigNode::loadString(
      "sensing:\n  profile: field\n  lidar: {range_noise_m: 0.03}\n  force: {drop_rate: 0.0}\n", "sim.yaml");
  const SensingSettings sensing = loadSimNodeSettings(root).simulator.sensing;
  EXPECT_EQ(sensing.profile, SensingProfile::kField);
  EXPECT_DOUBLE_EQ(sensing.lidar.range_noise_m, 0.03);
  EXPECT_DOUBLE_EQ(sensing.force.drop_rate, 0.0);
  const SensingSettings field = sensingProfile(SensingProfile::kField);
  EXPECT_DOUBLE_EQ(sensing.lidar.dropout_rate, field.lidar.dropout_rate);
  EXPECT_DOUBLE_EQ(sensing.pose.latency_s, field.pose.latency_s);
  EXPECT_EQ(sensing.wheels.encoder_counts_per_rev, field.wheels.encoder_counts_per_rev);
  EXPECT_NO_THROW(root.rejectUnknownKeys());
}

TEST(SensingConfig, AProfileFromTheCommandLineReplacesTheFilesAndKeepsItsOverrides)
{
  const auto root =
      common::ConfigNode::loadString("sensing:\n  profile: ideal\n  pose: {latency_s: 0.1}\n", "sim.yaml");
  const SensingSettings ideal = loadSimNodeSettings(root).simulator.sensing;
  EXPECT_EQ(ideal.profile, SensingProfile::kIdeal);
  EXPECT_DOUBLE_EQ(ideal.pose.latency_s, 0.1);
  EXPECT_FALSE(ideal.pose.drifts());
  const SensingSettings field = loadSimNodeSettings(root, SensingProfile::kField).simulator.sensing;
  EXPECT_EQ(field.profile, SensingProfile::kField);
  EXPECT_DOUBLE_EQ(field.pose.latency_s, 0.1);
  EXPECT_TRUE(field.pose.drifts());
  EXPECT_DOUBLE_EQ(field.lidar.range_noise_m, sensingProfile("field").lidar.range_noise_m);
}

TEST(SensingConfig, TheOldPoseNoiseKeysSetTheJitter)
{
  const auto root = common::ConfigNode::loadString(
      "pose:\n  noise_position_m: 0.02\n  noise_heading_rad: 0.01\n", "sim.yaml");
  const SensingSettings sensing = loadSimNodeSettings(root).simulator.sensing;
  EXPECT_DOUBLE_EQ(sensing.pose.jitter_position_m, 0.02);
  EXPECT_DOUBLE_EQ(sensing.pose.jitter_heading_rad, 0.01);
  EXPECT_EQ(sensing.profile, SensingProfile::kIdeal);
}

TEST(SensingConfig, BadValuesNameTheKey)
{
  for (const char* text : {"sensing:\n  lidar: {dropout_rate: 1.5}\n", "sensing:\n  profile: noisy\n",
                           "sensing:\n  pose: {correction_fraction: -0.1}\n",
                           "sensing:\n  wheels: {encoder_counts_per_rev: -4}\n"}) {
    const auto root = common::ConfigNode::loadString(text, "sim.yaml");
    try {
      loadSimNodeSettings(root);
      ADD_FAILURE() << "expected a config error for " << text;
    } catch (const common::ConfigError& error) {
      EXPECT_NE(std::string(error.what()).find("sensing."), std::string::npos) << error.what();
    }
  }
  const auto typo = common::ConfigNode::loadString("sensing:\n  lidar: {range_noise: 0.03}\n", "sim.yaml");
  loadSimNodeSettings(typo);
  EXPECT_THROW(typo.rejectUnknownKeys(), common::ConfigError);
}

// The reference (docs/configuration.md) quotes each key's field value: it must be the profile's.
TEST(SensingConfig, TheMeaningsQuoteTheFieldProfilesValues)
{
  SimNodeSettings field;
  field.simulator.sensing = sensingProfile(SensingProfile::kField);
  const auto infos = simNodeParameters().infos();
  const auto values = simNodeParameters().values(field);
  int quoted = 0;
  for (std::size_t index = 0; index < infos.size(); ++index) {
    const std::string& meaning = infos[index].meaning;
    const auto at = meaning.find("(field ");
    if (infos[index].key.rfind("sensing.", 0) != 0 || at == std::string::npos) {
      continue;
    }
    const double value = std::holds_alternative<double>(values[index])
                             ? std::get<double>(values[index])
                             : static_cast<double>(std::get<std::int64_t>(values[index]));
    const std::string written = common::formatNumber(value);
    EXPECT_EQ(meaning.compare(at + 7, written.size(), written), 0) << infos[index].key << ": " << meaning;
    EXPECT_TRUE(meaning.size() > at + 7 + written.size() &&
                (meaning[at + 7 + written.size()] == ')' || meaning[at + 7 + written.size()] == ':'))
        << infos[index].key << ": " << meaning;
    ++quoted;
  }
  EXPECT_GE(quoted, 20);
}

TEST(SensingStreams, AreIndependentOfEachOther)
{
  EXPECT_NE(sensingStreamSeed(1, kPoseDriftStream), sensingStreamSeed(1, kLidarStream));
  EXPECT_NE(sensingStreamSeed(1, kLidarStream), sensingStreamSeed(2, kLidarStream));
  EXPECT_EQ(sensingStreamSeed(7, kForceStream), sensingStreamSeed(7, kForceStream));
}

}  // namespace
}  // namespace ifar::sim
