#include "drivers/velodyne/driver_settings.hpp"

#include <gtest/gtest.h>

#include <string>

namespace ifar::velodyne {
namespace {

using common::ConfigError;
using common::ConfigNode;

TEST(VelodyneDriverSettings, DefaultsWhenEmpty)
{
  const DriverSettings settings = loadDriverSettings(ConfigNode::loadString("{}", "test.yaml"));
  EXPECT_EQ(settings.data_port, 2368);
  EXPECT_EQ(settings.position_port, 8308);
  EXPECT_FALSE(settings.position_packets);
  EXPECT_EQ(settings.data_channel, "VELODYNE_PACKET");
  EXPECT_EQ(settings.status_channel, "VELODYNE_STATUS");
}

TEST(VelodyneDriverSettings, ShippedConfigLoadsCompletely)
{
  const auto node = ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/velodyne.yaml");
  const DriverSettings settings = loadDriverSettings(node);
  node.optional<std::string>("log_level", "");
  EXPECT_NO_THROW(node.rejectUnknownKeys());
  EXPECT_EQ(settings.data_port, 2368);
  EXPECT_EQ(settings.receive_buffer_bytes, 4194304);
}

TEST(VelodyneDriverSettings, AwaitedPacketsNameTheSensorOrThePort)
{
  DriverSettings settings = loadDriverSettings(ConfigNode::loadString("{}", "v.yaml"));
  EXPECT_EQ(awaitedPackets(settings), "lidar packets on port 2368");
  settings = loadDriverSettings(
      ConfigNode::loadString("sensor_address: 192.168.1.201\ndata_port: 2400\n", "v.yaml"));
  EXPECT_EQ(awaitedPackets(settings), "lidar packets from 192.168.1.201:2400");
}

TEST(VelodyneDriverSettings, SensorModelIsAutoUnlessNamed)
{
  EXPECT_EQ(loadDriverSettings(ConfigNode::loadString("{}", "v.yaml")).sensor_model, SensorModel::kAuto);
  EXPECT_EQ(loadDriverSettings(ConfigNode::loadString("sensor_model: auto", "v.yaml")).sensor_model,
            SensorModel::kAuto);
  EXPECT_EQ(loadDriverSettings(ConfigNode::loadString("sensor_model: VLP-16", "v.yaml")).sensor_model,
            SensorModel::kVlp16);
  try {
    loadDriverSettings(ConfigNode::loadString("sensor_model: HDL-32E", "v.yaml"));
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "v.yaml: key 'sensor_model': must be one of auto, VLP-16, got 'HDL-32E'");
  }
}

TEST(VelodyneDriverSettings, BadValuesNameTheKey)
{
  try {
    loadDriverSettings(ConfigNode::loadString("data_port: 70000", "velodyne.yaml"));
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("data_port"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("70000"), std::string::npos) << error.what();
  }
  EXPECT_THROW(loadDriverSettings(ConfigNode::loadString("status_period_s: 0", "v.yaml")), ConfigError);
  EXPECT_THROW(loadDriverSettings(ConfigNode::loadString("position_packets: maybe", "v.yaml")), ConfigError);
  try {
    loadDriverSettings(ConfigNode::loadString("bind_address: 999.1.1.1", "v.yaml"));
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "v.yaml: key 'bind_address': must be an IPv4 address such as 0.0.0.0 or 192.168.1.77, got "
              "'999.1.1.1'");
  }
}

}  // namespace
}  // namespace ifar::velodyne
