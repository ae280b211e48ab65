// The planner daemon's settings: the shipped config/planner.yaml loads as a whole, and bad values name
// the key.

#include <string>

#include <gtest/gtest.h>

#include "common/config.hpp"
#include "planner/daemon/daemon_settings.hpp"

namespace ifar::planner {
namespace {

TEST(PlannerDaemonConfig, ShippedFileLoadsAndPassesRejectUnknownKeys)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/planner.yaml");
  const PlannerConfig config = loadPlannerConfig(root);
  EXPECT_DOUBLE_EQ(config.daemon.rate_hz, 2.5);
  EXPECT_DOUBLE_EQ(config.daemon.input.stale_input_age_s, 0.5);
  EXPECT_EQ(config.daemon.channels.velodyne_packet, "VELODYNE_PACKET");
  EXPECT_EQ(config.daemon.channels.planner_status, "PLANNER_STATUS");
  EXPECT_EQ(config.daemon.vehicle_config, "config/vehicle.yaml");
  EXPECT_DOUBLE_EQ(config.planner.perception.cell_size_m, 0.15);
  EXPECT_EQ(config.planner.graph.votes, 10);
}

TEST(PlannerDaemonConfig, MissingDaemonSectionUsesDefaults)
{
  const auto root = common::ConfigNode::loadString("daemon: {}\n", "inline");
  const DaemonSettings settings = loadDaemonSettings(root);
  EXPECT_DOUBLE_EQ(settings.rate_hz, 2.5);
  EXPECT_EQ(settings.channels.goal, "GOAL");
}

TEST(PlannerDaemonConfig, BadValuesNameTheKey)
{
  const auto negative = common::ConfigNode::loadString("daemon:\n  rate_hz: -1\n", "bad.yaml");
  try {
    loadDaemonSettings(negative);
    FAIL() << "negative rate accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("rate_hz"), std::string::npos) << error.what();
  }
  const auto unknown = common::ConfigNode::loadString("daemon:\n  rate: 2\n", "bad.yaml");
  EXPECT_THROW(loadDaemonSettings(unknown), common::ConfigError);
  const auto empty_channel =
      common::ConfigNode::loadString("daemon:\n  channels:\n    pose: \"\"\n", "bad.yaml");
  EXPECT_THROW(loadDaemonSettings(empty_channel), common::ConfigError);
}

}  // namespace
}  // namespace ifar::planner
