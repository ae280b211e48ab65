#include "drivers/motor/motor_config.hpp"

#include <gtest/gtest.h>

namespace ifar::motor {
namespace {

TEST(MotorConfig, ReadsTheProjectConfig)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/can.yaml");
  common::VehicleSettings vehicle;
  vehicle.wheel_radius_m = 0.2;
  const MotorConfig config = loadMotorConfig(root, vehicle);
  EXPECT_EQ(config.drive.left.node_id, 1);
  EXPECT_EQ(config.drive.right.node_id, 2);
  EXPECT_EQ(config.drive.left.heartbeat_timeout_us, 300'000);
  EXPECT_EQ(config.drive.right.command_timeout_us, 200'000);
  EXPECT_EQ(config.cycle_us, 10'000);
  EXPECT_DOUBLE_EQ(config.drive.wheel_radius_m, 0.2);
  EXPECT_EQ(config.status_channel, "MOTOR_STATUS");
}

TEST(MotorConfig, RejectsEqualNodeIdsNamingTheKey)
{
  const auto root =
      common::ConfigNode::loadString("motor:\n  left_node_id: 3\n  right_node_id: 3\n", "test.yaml");
  try {
    loadMotorConfig(root, common::VehicleSettings{});
    FAIL() << "equal node ids accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("right_node_id"), std::string::npos) << error.what();
  }
}

TEST(MotorConfig, RejectsNodeIdOutOfRange)
{
  const auto root =
      common::ConfigNode::loadString("motor:\n  left_node_id: 0\n  right_node_id: 2\n", "test.yaml");
  EXPECT_THROW(loadMotorConfig(root, common::VehicleSettings{}), common::ConfigError);
}

}  // namespace
}  // namespace ifar::motor
