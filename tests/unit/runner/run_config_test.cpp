// The runner reads the daemons' config files with their strict loaders.

#include "system/run_config.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/config.hpp"

namespace ifar::runner {
namespace {

const std::string kConfigDir = std::string(IFAR_SOURCE_DIR) + "/config";

TEST(RunnerConfig, ReadsTheShippedConfig)
{
  const RunRequest request = loadRunSettings(kConfigDir);
  const common::VehicleSettings vehicle =
      common::loadVehicleSettings(common::ConfigNode::loadFile(kConfigDir + "/vehicle.yaml"));
  EXPECT_DOUBLE_EQ(request.vehicle.mass_kg, vehicle.mass_kg);
  EXPECT_DOUBLE_EQ(request.planner.vehicle.width_m, vehicle.width_m);
  EXPECT_DOUBLE_EQ(request.planner.interaction.pusher.max_push_force_n, vehicle.maxPushForce());
  EXPECT_DOUBLE_EQ(request.planner_node.rate_hz, 2.5);
  EXPECT_DOUBLE_EQ(request.planner_node.path_resend_hz, 20.0);
  EXPECT_EQ(request.planner_node.data_port, 2368);
  EXPECT_DOUBLE_EQ(request.sim.simulator.physics.step_seconds, 1.0 / 200.0);
  EXPECT_TRUE(request.sim.simulator.lidar_enabled);
  EXPECT_EQ(request.sim.simulator.seed, 1U);
  EXPECT_DOUBLE_EQ(request.sim.pose_rate_hz, 50.0);
  EXPECT_EQ(request.sim.lidar_port, 2368);
  EXPECT_EQ(request.velodyne.data_port, 2368);
  EXPECT_EQ(request.velodyne.data_channel, "VELODYNE_PACKET");
  EXPECT_EQ(request.force_sensor.channel, "FORCE");
  EXPECT_EQ(request.force_sensor.monitor.frame_id, 400U);
  EXPECT_EQ(request.motor.cycle_us, 10'000);
  EXPECT_EQ(request.motor.drive.left.node_id, 1);
  EXPECT_DOUBLE_EQ(request.motor.drive.wheel_radius_m, vehicle.wheel_radius_m);
  EXPECT_EQ(request.can_channel, "CAN_VEHICLE");
  EXPECT_DOUBLE_EQ(request.executive.goal_tolerance_m, 0.3);
  EXPECT_DOUBLE_EQ(request.obstacles.keep_s, 0.15);
}

class RunnerConfigCopy : public ::testing::Test {
 protected:
  void SetUp() override
  {
    directory_ =
        std::filesystem::path(IFAR_BINARY_DIR) / "tests" /
        ("runner_config_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
    for (const char* file :
         {"vehicle.yaml", "planner.yaml", "executive.yaml", "sim.yaml", "can.yaml", "velodyne.yaml"}) {
      std::filesystem::copy_file(std::filesystem::path(kConfigDir) / file, directory_ / file);
    }
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  void append(const std::string& file, const std::string& text) const
  {
    std::ofstream out(directory_ / file, std::ios::app);
    out << text;
  }
  void replace(const std::string& file, const std::string& from, const std::string& to) const
  {
    std::ifstream in(directory_ / file);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(directory_ / file, std::ios::trunc) << text;
  }
  std::filesystem::path directory_;
};

TEST_F(RunnerConfigCopy, UnknownKeyNamesFileAndKey)
{
  append("executive.yaml", "\nwaypoint_tolerence_m: 0.4\n");
  try {
    loadRunSettings(directory_.string());
    FAIL() << "expected a config error";
  } catch (const common::ConfigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("executive.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("waypoint_tolerence_m"), std::string::npos) << message;
  }
}

TEST_F(RunnerConfigCopy, BadSimValueNamesKey)
{
  replace("sim.yaml", "\nseed: 1", "\nseed: -4");
  try {
    loadRunSettings(directory_.string());
    FAIL() << "expected a config error";
  } catch (const common::ConfigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("sim.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("seed"), std::string::npos) << message;
  }
}

TEST_F(RunnerConfigCopy, BadCanValueNamesFileAndKey)
{
  replace("can.yaml", "cycle_ms: 10", "cycle_ms: 0");
  try {
    loadRunSettings(directory_.string());
    FAIL() << "expected a config error";
  } catch (const common::ConfigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("can.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("cycle_ms"), std::string::npos) << message;
  }
}

TEST(RunnerConfig, MissingDirectoryIsAConfigError)
{
  EXPECT_THROW(loadRunSettings("/nonexistent/ifar/config"), common::ConfigError);
}

}  // namespace
}  // namespace ifar::runner
