#include "sim/node/node_settings.hpp"

#include <gtest/gtest.h>

#include "sim/lidar/udp_sender.hpp"

namespace ifar::sim {
namespace {

TEST(SimNodeSettings, ReadsTheCheckedInConfig)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/sim.yaml");
  const SimNodeSettings settings = loadSimNodeSettings(root);
  EXPECT_EQ(settings.lidar_host, "127.0.0.1");
  EXPECT_EQ(settings.lidar_port, 2368);
  EXPECT_DOUBLE_EQ(settings.simulator.physics.step_seconds, 1.0 / 200.0);
  EXPECT_DOUBLE_EQ(settings.pose_rate_hz, 50.0);
  EXPECT_EQ(settings.command_source, CommandSource::kCan);
  EXPECT_EQ(settings.can_config, "can.yaml");
  root.optional<std::string>("log_level", "");  // read by runDaemon
  EXPECT_NO_THROW(root.rejectUnknownKeys());
}

TEST(SimNodeSettings, BadValuesNameTheKey)
{
  const auto port = common::ConfigNode::loadString("lidar:\n  port: 70000\n", "sim.yaml");
  try {
    loadSimNodeSettings(port);
    FAIL() << "expected a config error";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("port"), std::string::npos) << error.what();
  }
  const auto source = common::ConfigNode::loadString("commands:\n  source: serial\n", "sim.yaml");
  EXPECT_THROW(loadSimNodeSettings(source), common::ConfigError);
  EXPECT_THROW(
      loadCanNodes(common::ConfigNode::loadString(
          "force_sensor: {frame_id: 400}\nmotor:\n  left_node_id: 3\n  right_node_id: 3\n", "can.yaml")),
      common::ConfigError);
}

// The emulated drives and force sensor answer to the ids the CAN drivers use: can.yaml is their one home.
TEST(SimNodeSettings, CanNodesComeFromTheDriversFile)
{
  const auto can = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/can.yaml");
  CanNodeSettings kept;
  kept.force_range_n = 500.0;
  const CanNodeSettings nodes = loadCanNodes(can, kept);
  EXPECT_EQ(nodes.left_node_id, 1);
  EXPECT_EQ(nodes.right_node_id, 2);
  EXPECT_EQ(nodes.force_frame_id, 0x190u);
  EXPECT_EQ(nodes.force_range_n, 500.0);
  const CanNodeSettings swapped = loadCanNodes(common::ConfigNode::loadString(
      "force_sensor: {frame_id: 401}\nmotor: {left_node_id: 5, right_node_id: 4}\n", "can.yaml"));
  EXPECT_EQ(swapped.left_node_id, 5);
  EXPECT_EQ(swapped.right_node_id, 4);
  EXPECT_EQ(swapped.force_frame_id, 0x191u);
}

TEST(UdpSender, RejectsAHostThatIsNotAnAddress)
{
  try {
    UdpSender sender("not-an-address", 2368);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("not-an-address:2368"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ifar::sim
