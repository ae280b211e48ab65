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
  EXPECT_EQ(settings.can_nodes.left_node_id, 1);
  EXPECT_EQ(settings.can_nodes.right_node_id, 2);
  EXPECT_EQ(settings.can_nodes.force_frame_id, 0x190u);
  root.acceptAllUnder("bus");                   // the daemon hands it to can::loadBusSettings
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
  const auto nodes =
      common::ConfigNode::loadString("can_nodes:\n  left_node_id: 3\n  right_node_id: 3\n", "sim.yaml");
  EXPECT_THROW(loadSimNodeSettings(nodes), common::ConfigError);
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
