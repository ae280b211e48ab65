#include <gtest/gtest.h>

#include "common/vehicle.hpp"

namespace {

TEST(Vehicle, CheckedInVehicleFileLoads)
{
  const auto node = ifar::common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/vehicle.yaml");
  const auto vehicle = ifar::common::loadVehicleSettings(node);
  EXPECT_GT(vehicle.width_m, 0.0);
  EXPECT_NEAR(vehicle.maxPushForce(), vehicle.traction_coefficient * vehicle.mass_kg * 9.81, 1e-9);
}

TEST(Vehicle, NonPositiveValueIsRejectedWithKey)
{
  std::string text = "length_m: 0.9\nwidth_m: -0.7\n";
  const auto node = ifar::common::ConfigNode::loadString(text, "vehicle.yaml");
  try {
    ifar::common::loadVehicleSettings(node);
    FAIL() << "no error";
  } catch (const ifar::common::ConfigError& error) {
    EXPECT_EQ(std::string(error.what()), "vehicle.yaml: key 'width_m': must be greater than 0 m, got -0.7");
  }
}

TEST(Vehicle, TheLidarFilterHasItsHomeHere)
{
  const auto node = ifar::common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/vehicle.yaml");
  const auto vehicle = ifar::common::loadVehicleSettings(node);
  EXPECT_EQ(vehicle.lidar.ground_clearance_m, 0.15);
  EXPECT_EQ(vehicle.lidar.max_height_m, 1.2);
  EXPECT_EQ(vehicle.lidar.min_range_m, 0.4);
  EXPECT_EQ(vehicle.lidar.movable_reflectivity_threshold, 101);
}

TEST(Vehicle, TheLidarHeightBandMustNotBeEmpty)
{
  // Every key 0.5 (the reflectivity threshold 101), but the lidar's height band upside down.
  std::string yaml;
  std::string lidar = "lidar:\n";
  for (const auto& info : ifar::common::vehicleParameters().infos()) {
    const bool under_lidar = info.key.rfind("lidar.", 0) == 0;
    const std::string name = under_lidar ? info.key.substr(6) : info.key;
    const std::string value = info.key == "lidar.max_height_m"
                                  ? "0.1"
                                  : (info.key == "lidar.movable_reflectivity_threshold" ? "101" : "0.5");
    (under_lidar ? lidar : yaml) += (under_lidar ? "  " : "") + name + ": " + value + "\n";
  }
  try {
    ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadString(yaml + lidar, "vehicle.yaml"));
    FAIL() << "no error";
  } catch (const ifar::common::ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "vehicle.yaml: key 'lidar.max_height_m': must be above lidar.ground_clearance_m");
  }
}

}  // namespace
