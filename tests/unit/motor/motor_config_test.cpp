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
  EXPECT_EQ(config.drive.right.command_timeout_us, 150'000);
  EXPECT_EQ(config.drive.left.sdo_timeout_us, 50'000);
  EXPECT_EQ(config.drive.left.sdo_attempts, 3);
  EXPECT_EQ(config.cycle_us, 10'000);
  EXPECT_EQ(config.master_node_id, 127);
  EXPECT_EQ(config.master_heartbeat_period_us, 50'000);
  EXPECT_EQ(config.command_future_tolerance_us, 50'000);
  EXPECT_EQ(config.drive_heartbeat_timeout_ms, 150);
  EXPECT_EQ(config.drive_rpdo_timeout_ms, 100);
  EXPECT_DOUBLE_EQ(config.drive.wheel_radius_m, 0.2);
  EXPECT_EQ(config.status_channel, "MOTOR_STATUS");
  EXPECT_EQ(config.odometry_channel, "ODOMETRY");
  EXPECT_EQ(config.odometry_timeout_us, 50'000);
}

TEST(MotorConfig, OdometryKeysAreOptionalAndChecked)
{
  const auto defaults = loadMotorConfig(
      common::ConfigNode::loadString("motor:\n  left_node_id: 1\n  right_node_id: 2\n", "test.yaml"),
      common::VehicleSettings{});
  EXPECT_EQ(defaults.odometry_channel, "ODOMETRY");
  EXPECT_EQ(defaults.odometry_timeout_us, 50'000);
  const auto set =
      loadMotorConfig(common::ConfigNode::loadString("motor:\n  left_node_id: 1\n  right_node_id: 2\n"
                                                     "  odometry_timeout_ms: 80\n"
                                                     "  odometry_channel: WHEELS\n",
                                                     "test.yaml"),
                      common::VehicleSettings{});
  EXPECT_EQ(set.odometry_channel, "WHEELS");
  EXPECT_EQ(set.odometry_timeout_us, 80'000);
  const auto zero = common::ConfigNode::loadString(
      "motor:\n  left_node_id: 1\n  right_node_id: 2\n  odometry_timeout_ms: 0\n", "test.yaml");
  try {
    loadMotorConfig(zero, common::VehicleSettings{});
    FAIL() << "odometry_timeout_ms 0 accepted";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("odometry_timeout_ms"), std::string::npos) << error.what();
  }
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

void expectRejected(const std::string& text, const std::string& key, const std::string& problem)
{
  const auto root = common::ConfigNode::loadString(text, "test.yaml");
  try {
    loadMotorConfig(root, common::VehicleSettings{});
    FAIL() << "accepted: " << text;
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find(key), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
  }
}

TEST(MotorConfig, RejectsADriveWatchdogThatWouldStopAHealthyDriver)
{
  expectRejected(
      "motor:\n  left_node_id: 1\n  right_node_id: 2\n  drive_watchdog:\n    rpdo_timeout_ms: 10\n",
      "rpdo_timeout_ms", "10 ms is not longer than cycle_ms (10 ms)");
  expectRejected(
      "motor:\n  left_node_id: 1\n  right_node_id: 2\n  master_heartbeat_ms: 100\n"
      "  drive_watchdog:\n    heartbeat_timeout_ms: 100\n",
      "heartbeat_timeout_ms", "not longer than master_heartbeat_ms");
  expectRejected(
      "motor:\n  left_node_id: 1\n  right_node_id: 2\n  drive_watchdog:\n    rpdo_timeout_ms: 70000\n",
      "rpdo_timeout_ms", "must be in [0, 65535] ms, got 70000");
  expectRejected("motor:\n  left_node_id: 1\n  right_node_id: 2\n  master_node_id: 2\n", "master_node_id",
                 "equals a drive's node id");
  expectRejected("motor:\n  left_node_id: 1\n  right_node_id: 2\n  sdo_attempts: 0\n", "sdo_attempts",
                 "must be in [1, 100], got 0");
}

TEST(MotorConfig, AZeroWatchdogTimeIsOff)
{
  const auto root = common::ConfigNode::loadString(
      "motor:\n  left_node_id: 1\n  right_node_id: 2\n  drive_watchdog:\n    heartbeat_timeout_ms: 0\n",
      "test.yaml");
  EXPECT_EQ(loadMotorConfig(root, common::VehicleSettings{}).drive_heartbeat_timeout_ms, 0);
}

}  // namespace
}  // namespace ifar::motor
