// The planner daemon's settings: the shipped config/planner.yaml loads as a whole, and bad values name
// the key.

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/config.hpp"
#include "planner/node/node_settings.hpp"

namespace ifar::planner {
namespace {

TEST(PlannerDaemonConfig, ShippedFileLoadsAndPassesRejectUnknownKeys)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/planner.yaml");
  const PlannerConfig config = loadPlannerConfig(root);
  EXPECT_DOUBLE_EQ(config.node.rate_hz, 2.5);
  EXPECT_DOUBLE_EQ(config.node.input.stale_input_age_s, 0.5);
  EXPECT_EQ(config.node.channels.velodyne_packet, "VELODYNE_PACKET");
  EXPECT_EQ(config.node.channels.planner_status, "PLANNER_STATUS");
  EXPECT_EQ(config.node.vehicle_config, "vehicle.yaml");
  EXPECT_DOUBLE_EQ(config.planner.perception.cell_size_m, 0.15);
  EXPECT_EQ(config.planner.graph.votes, 10);
  EXPECT_DOUBLE_EQ(config.node.path_resend_hz, 20.0);
  EXPECT_TRUE(config.planner.interaction_enabled);
  EXPECT_DOUBLE_EQ(config.planner.interaction.loop.frame_budget_ms, 50.0);
  EXPECT_DOUBLE_EQ(config.planner.interaction.loop.default_physics.mass_kg, 20.0);
  EXPECT_DOUBLE_EQ(config.planner.interaction.loop.default_physics.ground_friction, 0.4);
  EXPECT_DOUBLE_EQ(config.planner.interaction.search.passage_margin_m, 0.15);
}

TEST(PlannerDaemonConfig, InteractionSectionIsReadStrictly)
{
  std::ifstream file(std::string(IFAR_SOURCE_DIR) + "/config/planner.yaml");
  std::stringstream text;
  text << file.rdbuf();
  std::string yaml = text.str();
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = yaml.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    yaml.replace(at, from.size(), to);
  };
  replace("  enabled: true", "  enabled: false");
  replace("  frame_budget_ms: 50.0", "  frame_budget_ms: 20");
  replace("  default_mass_kg: 20.0", "  default_mass_kg: 35");
  const PlannerConfig config = loadPlannerConfig(common::ConfigNode::loadString(yaml, "far.yaml"));
  EXPECT_FALSE(config.planner.interaction_enabled);
  EXPECT_DOUBLE_EQ(config.planner.interaction.loop.frame_budget_ms, 20.0);
  EXPECT_DOUBLE_EQ(config.planner.interaction.loop.default_physics.mass_kg, 35.0);

  replace("  frame_budget_ms: 20", "  frame_budget: 20");
  try {
    loadPlannerConfig(common::ConfigNode::loadString(yaml, "bad.yaml"));
    ADD_FAILURE() << "misspelt key accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("frame_budget"), std::string::npos) << error.what();
  }
  replace("  frame_budget: 20", "  frame_budget_ms: 20");
  replace("  default_mass_kg: 35", "  default_mass_kg: -3");
  try {
    loadPlannerConfig(common::ConfigNode::loadString(yaml, "bad.yaml"));
    ADD_FAILURE() << "negative mass accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("default_mass_kg"), std::string::npos) << error.what();
  }
  try {
    loadNodeSettings(common::ConfigNode::loadString("daemon:\n  path_resend_hz: 0\n", "bad.yaml"));
    ADD_FAILURE() << "zero resend rate accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("path_resend_hz"), std::string::npos) << error.what();
  }
}

TEST(PlannerDaemonConfig, MissingDaemonSectionUsesDefaults)
{
  const auto root = common::ConfigNode::loadString("daemon: {}\n", "inline");
  const NodeSettings settings = loadNodeSettings(root);
  EXPECT_DOUBLE_EQ(settings.rate_hz, 2.5);
  EXPECT_EQ(settings.channels.goal, "GOAL");
}

TEST(PlannerDaemonConfig, BadValuesNameTheKey)
{
  const auto negative = common::ConfigNode::loadString("daemon:\n  rate_hz: -1\n", "bad.yaml");
  try {
    loadNodeSettings(negative);
    FAIL() << "negative rate accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("rate_hz"), std::string::npos) << error.what();
  }
  const auto unknown = common::ConfigNode::loadString("daemon:\n  rate: 2\n", "bad.yaml");
  EXPECT_THROW(loadNodeSettings(unknown), common::ConfigError);
  const auto empty_channel =
      common::ConfigNode::loadString("daemon:\n  channels:\n    pose: \"\"\n", "bad.yaml");
  EXPECT_THROW(loadNodeSettings(empty_channel), common::ConfigError);
}

}  // namespace
}  // namespace ifar::planner
