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
    EXPECT_EQ(std::string(error.what()).rfind("vehicle.yaml: key 'width_m': must be greater than zero", 0),
              0U)
        << error.what();
  }
}

}  // namespace
