// The vehicle launch keeps its own configuration: launch/vehicle.yaml gives the drivers onboard/ files
// (SocketCAN, the sensor's address) that load with the drivers' own loaders and differ from the simulator
// stack's can.yaml and velodyne.yaml in those keys only, so node ids and timeouts cannot drift apart.

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <string>

#include <yaml-cpp/yaml.h>

#include "common/config.hpp"
#include "drivers/can/open_bus.hpp"
#include "drivers/velodyne/driver_settings.hpp"
#include "tools/launch/launch_config.hpp"

namespace ifar {
namespace {

const std::string kConfig = std::string(IFAR_SOURCE_DIR) + "/config/";

/// Every scalar of a YAML file by dotted key.
std::map<std::string, std::string> leaves(const std::string& path)
{
  std::map<std::string, std::string> result;
  const std::function<void(const YAML::Node&, const std::string&)> walk = [&](const YAML::Node& node,
                                                                              const std::string& prefix) {
    if (node.IsMap()) {
      for (const auto& entry : node) {
        walk(entry.second,
             prefix.empty() ? entry.first.as<std::string>() : prefix + "." + entry.first.as<std::string>());
      }
    } else {
      result[prefix] = node.IsScalar() ? node.as<std::string>() : YAML::Dump(node);
    }
  };
  walk(YAML::LoadFile(path), "");
  return result;
}

/// The keys whose values differ between two files, and the keys only one of them has.
std::map<std::string, std::string> differences(const std::string& first, const std::string& second)
{
  const auto a = leaves(first);
  const auto b = leaves(second);
  std::map<std::string, std::string> different;
  for (const auto& [key, value] : a) {
    const auto other = b.find(key);
    if (other == b.end() || other->second != value) {
      different[key] = value + " / " + (other == b.end() ? "(absent)" : other->second);
    }
  }
  for (const auto& [key, value] : b) {
    if (a.count(key) == 0) {
      different[key] = "(absent) / " + value;
    }
  }
  return different;
}

TEST(OnboardConfig, CanDiffersFromTheSimulatorsInTheBusKindOnly)
{
  const std::map<std::string, std::string> expected = {{"bus.kind", "lcm / socketcan"}};
  EXPECT_EQ(differences(kConfig + "can.yaml", kConfig + "onboard/can.yaml"), expected);
  const auto root = common::ConfigNode::loadFile(kConfig + "onboard/can.yaml");
  const can::BusSettings bus = can::loadBusSettings(root);
  EXPECT_EQ(bus.kind, can::BusKind::kSocketCan);
  EXPECT_EQ(bus.interface, "can0");
  EXPECT_EQ(bus.bitrate, 500000);
  EXPECT_EQ(bus.restart_ms, 100);
}

TEST(OnboardConfig, VelodyneTakesTheSensorsAddressOnly)
{
  const std::map<std::string, std::string> expected = {{"sensor_address", " / 192.168.1.201"}};
  EXPECT_EQ(differences(kConfig + "velodyne.yaml", kConfig + "onboard/velodyne.yaml"), expected);
  const auto root = common::ConfigNode::loadFile(kConfig + "onboard/velodyne.yaml");
  root.optional<std::string>("log_level", "");  // runDaemon's key
  const velodyne::DriverSettings settings = velodyne::loadDriverSettings(root);
  EXPECT_NO_THROW(root.rejectUnknownKeys());
  EXPECT_EQ(settings.sensor_address, "192.168.1.201");
  EXPECT_EQ(settings.data_port, 2368);
}

TEST(VehicleLaunch, DriversReadTheOnboardFilesAndNothingSimulated)
{
  const launch::LaunchSpec spec =
      launch::loadLaunchSpec(common::ConfigNode::loadFile(kConfig + "launch/vehicle.yaml"),
                             [](const std::string&) { return std::nullopt; });
  std::map<std::string, std::string> config_of;
  for (const launch::ProcessSpec& process : spec.processes) {
    EXPECT_NE(process.command.front(), "ifar-sim") << "the vehicle launch starts a simulator";
    EXPECT_NE(process.command.front(), "ifar-goal") << "the vehicle launch sends a goal";
    for (std::size_t index = 0; index + 1 < process.command.size(); ++index) {
      if (process.command[index] == "--config") {
        config_of[process.name] = process.command[index + 1];
      }
    }
  }
  const std::map<std::string, std::string> expected = {
      {"velodyne", "onboard/velodyne.yaml"}, {"force", "onboard/can.yaml"}, {"motors", "onboard/can.yaml"}};
  EXPECT_EQ(config_of, expected);
  EXPECT_EQ(spec.processes.size(), 6u);
}

}  // namespace
}  // namespace ifar
