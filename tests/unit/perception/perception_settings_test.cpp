#include "planner/perception/perception_settings.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace ifar::perception {
namespace {

const char* const kValid = R"(
perception:
  layer_size_m: 40.0
  cell_size_m: 0.2
  inflation_radius_m: 0.4
  exact_inflation: true
  simplify_epsilon_m: 0.05
  min_polygon_area_m2: 0.1
  tag_neighbourhood_m: 0.3
  no_path_forget_limit: 2
  scan_trust_range_m: 4.0
  remember_background: false
  gap_fill_azimuth_step_deg: 0.5
  gap_fill_min_incidence_deg: 4.0
  carve_range_m: 15.0
  carve_margin_m: 0.2
  background_votes: 3
)";

std::string messageOf(const std::string& text)
{
  try {
    loadPerceptionSettings(common::ConfigNode::loadString(text, "planner.yaml"));
  } catch (const common::ConfigError& error) {
    return error.what();
  }
  return "no error";
}

std::string replaced(const std::string& from, const std::string& to)
{
  std::string text = kValid;
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(PerceptionSettings, ReadsEveryKey)
{
  const PerceptionSettings settings = loadPerceptionSettings(common::ConfigNode::loadString(kValid, "test"));
  EXPECT_DOUBLE_EQ(settings.layer_size_m, 40.0);
  EXPECT_DOUBLE_EQ(settings.cell_size_m, 0.2);
  EXPECT_DOUBLE_EQ(settings.inflation_radius_m, 0.4);
  EXPECT_DOUBLE_EQ(settings.simplify_epsilon_m, 0.05);
  EXPECT_TRUE(settings.exact_inflation);
  EXPECT_DOUBLE_EQ(settings.min_polygon_area_m2, 0.1);
  EXPECT_FALSE(settings.remember_background);
  EXPECT_DOUBLE_EQ(settings.tag_neighbourhood_m, 0.3);
  EXPECT_EQ(settings.no_path_forget_limit, 2);
  EXPECT_DOUBLE_EQ(settings.scan_trust_range_m, 4.0);
  EXPECT_DOUBLE_EQ(settings.gap_fill_azimuth_step_deg, 0.5);
  EXPECT_DOUBLE_EQ(settings.gap_fill_min_incidence_deg, 4.0);
  EXPECT_DOUBLE_EQ(settings.carve_range_m, 15.0);
  EXPECT_DOUBLE_EQ(settings.carve_margin_m, 0.2);
  EXPECT_EQ(settings.background_votes, 3);
  EXPECT_EQ(settings.layerCells(), 200);
}

TEST(PerceptionSettings, TheLidarFilterIsTheVehicles)
{
  common::LidarFilterSettings lidar;
  lidar.ground_clearance_m = 0.2;
  lidar.max_height_m = 1.5;
  lidar.min_range_m = 0.5;
  lidar.movable_reflectivity_threshold = 120;
  const PerceptionSettings settings = withLidarFilter(PerceptionSettings{}, lidar);
  EXPECT_EQ(settings.ground_clearance_m, 0.2);
  EXPECT_EQ(settings.vehicle_height_m, 1.5);
  EXPECT_EQ(settings.min_range_m, 0.5);
  EXPECT_EQ(settings.movable_reflectivity_threshold, 120.0F);
  EXPECT_EQ(settings.cell_size_m, PerceptionSettings{}.cell_size_m);
}

TEST(PerceptionSettings, ProjectConfigLoads)
{
  const PerceptionSettings settings = loadPerceptionSettings(
      common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/planner.yaml"));
  EXPECT_DOUBLE_EQ(settings.layer_size_m, 200.0);
  EXPECT_DOUBLE_EQ(settings.cell_size_m, 0.15);
  EXPECT_EQ(settings.layerCells(), 1334);
  EXPECT_DOUBLE_EQ(settings.inflation_radius_m, 0.35);
}

TEST(PerceptionSettings, BadValuesNameTheKey)
{
  EXPECT_NE(messageOf(replaced("cell_size_m: 0.2", "cell_size_m: -0.2")).find("cell_size_m"),
            std::string::npos);
  EXPECT_EQ(messageOf(replaced("cell_size_m: 0.2", "cell_size_m: 0")),
            "planner.yaml: key 'perception.cell_size_m': must be greater than 0 m, got 0");
  EXPECT_NE(messageOf(replaced("cell_size_m: 0.2", "cell_size_m: 50")).find("must not exceed layer_size_m"),
            std::string::npos);
  EXPECT_NE(messageOf(replaced("layer_size_m: 40.0", "layer_size_m: wide")).find("layer_size_m"),
            std::string::npos);
  EXPECT_NE(messageOf(replaced("  cell_size_m: 0.2\n", "")).find("cell_size_m"), std::string::npos);
  EXPECT_NE(messageOf(replaced("cell_size_m: 0.2", "cell_size_m: 0.2\n  colour: red")).find("colour"),
            std::string::npos);
  // The lidar filter moved to vehicle.yaml lidar:; the old key here is unknown.
  EXPECT_NE(
      messageOf(replaced("cell_size_m: 0.2", "cell_size_m: 0.2\n  min_range_m: 0.4")).find("min_range_m"),
      std::string::npos);
  EXPECT_NE(messageOf("graph: {}\n").find("perception"), std::string::npos);
  EXPECT_NE(messageOf(replaced("gap_fill_azimuth_step_deg: 0.5", "gap_fill_azimuth_step_deg: -0.5"))
                .find("gap_fill_azimuth_step_deg"),
            std::string::npos);
  // A join spans up to 1.25 azimuth steps, so the incidence must be above that.
  EXPECT_NE(messageOf(replaced("gap_fill_min_incidence_deg: 4.0", "gap_fill_min_incidence_deg: 0.6"))
                .find("gap_fill_min_incidence_deg"),
            std::string::npos);
  EXPECT_EQ(messageOf(replaced("gap_fill_azimuth_step_deg: 0.5", "gap_fill_azimuth_step_deg: 0")),
            "no error");
}

TEST(PerceptionSettings, ProblemsInProgrammaticSettingsNameTheField)
{
  EXPECT_FALSE(findSettingsProblem(PerceptionSettings{}).has_value());
  PerceptionSettings settings;
  settings.cell_size_m = 0.0;
  ASSERT_TRUE(findSettingsProblem(settings).has_value());
  EXPECT_NE(findSettingsProblem(settings)->find("cell_size_m"), std::string::npos);
  settings = PerceptionSettings{};
  settings.inflation_radius_m = std::nan("");
  EXPECT_NE(findSettingsProblem(settings).value_or("").find("inflation_radius_m"), std::string::npos);
  settings = PerceptionSettings{};
  settings.cell_size_m = 1e-6;  // 60 million cells a side
  EXPECT_TRUE(findSettingsProblem(settings).has_value());
  settings = PerceptionSettings{};
  settings.vehicle_height_m = 0.1;
  EXPECT_NE(findSettingsProblem(settings).value_or("").find("vehicle_height_m"), std::string::npos);
  settings = PerceptionSettings{};
  settings.gap_fill_azimuth_step_deg = 0.2;
  settings.gap_fill_min_incidence_deg = 90.0;
  EXPECT_NE(findSettingsProblem(settings).value_or("").find("gap_fill_min_incidence_deg"), std::string::npos);
}

}  // namespace
}  // namespace ifar::perception
