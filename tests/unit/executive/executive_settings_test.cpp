#include "executive/modes/executive_settings.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "executive/modes/executive.hpp"

namespace ifar::executive {
namespace {

const std::string kConfigPath = std::string(IFAR_SOURCE_DIR) + "/config/executive.yaml";
const std::string kVehiclePath = std::string(IFAR_SOURCE_DIR) + "/config/vehicle.yaml";

TEST(ExecutiveSettings, LoadsShippedConfig)
{
  const common::VehicleSettings vehicle =
      common::loadVehicleSettings(common::ConfigNode::loadFile(kVehiclePath));
  const ExecutiveSettings settings = loadExecutiveSettings(common::ConfigNode::loadFile(kConfigPath));
  EXPECT_DOUBLE_EQ(settings.stale.pose_s, 0.1);
  EXPECT_DOUBLE_EQ(settings.stale.motor_s, 0.3);
  EXPECT_DOUBLE_EQ(settings.reference_to_bumper_m, 0.45);
  const Executive executive(settings, vehicle);
  const Footprint& footprint = executive.settings().follower.footprint;
  EXPECT_DOUBLE_EQ(footprint.front_m, 0.45);
  EXPECT_DOUBLE_EQ(footprint.rear_m, vehicle.length_m - 0.45);
  EXPECT_DOUBLE_EQ(footprint.half_width_m, vehicle.width_m / 2.0);
  EXPECT_EQ(settings.follower.angular_samples, 15);
  EXPECT_DOUBLE_EQ(settings.tactile.no_motion_time_s, 2.0);
  EXPECT_DOUBLE_EQ(settings.tactile.contact_force_n, settings.approach.contact_force_n);
  EXPECT_DOUBLE_EQ(settings.tactile.pose_smoothing_s, 0.1);
  EXPECT_DOUBLE_EQ(settings.stale.odometry_s, 0.1);
  EXPECT_TRUE(settings.doorway.enabled);
  EXPECT_DOUBLE_EQ(settings.doorway.max_width_m, 1.2);
  EXPECT_DOUBLE_EQ(settings.doorway.speed, 0.6);
  EXPECT_EQ(settings.blocked_passage_on_sight, GapReportScope::NearPushedObjects);
  EXPECT_DOUBLE_EQ(settings.gap_report_repeat_s, 2.0);
}

/// The error loading the shipped executive.yaml with `line` replaced by `replacement` raises; empty when
/// it loads (or the line is not there: a failed expectation names it).
std::string errorWithLineReplaced(const std::string& line, const std::string& replacement)
{
  std::ifstream file(kConfigPath);
  EXPECT_TRUE(file.good()) << kConfigPath;
  std::stringstream original;
  original << file.rdbuf();
  std::string text = original.str();
  const std::size_t at = text.find(line);
  EXPECT_NE(at, std::string::npos) << line;
  if (at == std::string::npos) {
    return {};
  }
  text.replace(at, line.size(), replacement);
  try {
    loadExecutiveSettings(common::ConfigNode::loadString(text, "edited.yaml"));
  } catch (const common::ConfigError& error) {
    return error.what();
  }
  return {};
}

TEST(ExecutiveSettings, DoorwaySearchThatStartsBeyondItsEndNamesTheKey)
{
  const std::string error = errorWithLineReplaced("  min_ahead_m: 0.8", "  min_ahead_m: 3.5");
  EXPECT_NE(error.find("doorway.min_ahead_m"), std::string::npos) << error;
  EXPECT_NE(error.find("less than doorway.look_ahead_m"), std::string::npos) << error;
}

TEST(ExecutiveSettings, AnUnknownGapReportScopeNamesTheKeyAndTheChoices)
{
  const std::string error = errorWithLineReplaced("blocked_passage_on_sight: near_pushed_objects",
                                                  "blocked_passage_on_sight: true");
  EXPECT_NE(error.find("edited.yaml: key 'blocked_passage_on_sight'"), std::string::npos) << error;
  EXPECT_NE(error.find("must be one of off, near_pushed_objects, everywhere, got 'true'"), std::string::npos)
      << error;
}

TEST(ExecutiveSettings, NegativeThresholdNamesTheKey)
{
  std::string text = "stale_after_s: {pose: -0.1, path: 1, force: 0.1, motor: 0.3, obstacles: 0.5}\n";
  try {
    loadExecutiveSettings(common::ConfigNode::loadString(text, "bad.yaml"));
    FAIL() << "accepted a negative threshold";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("stale_after_s.pose"), std::string::npos) << error.what();
  }
}

TEST(ExecutiveSettings, OdometryAndSmoothingKeysAreRequiredAndChecked)
{
  EXPECT_NE(errorWithLineReplaced("  odometry: 0.1", "  odometry: 0").find("stale_after_s.odometry"),
            std::string::npos);
  EXPECT_NE(errorWithLineReplaced("  pose_smoothing_s: 0.1", "  pose_smoothing_s: -0.1")
                .find("tactile.pose_smoothing_s"),
            std::string::npos);
  EXPECT_NE(errorWithLineReplaced("  pose_smoothing_s: 0.1", "").find("tactile.pose_smoothing_s"),
            std::string::npos);
  EXPECT_EQ(errorWithLineReplaced("  pose_smoothing_s: 0.1", "  pose_smoothing_s: 0"), "");  // the raw pose
}

TEST(ExecutiveSettings, UnknownKeyIsRejected)
{
  std::ifstream file(kConfigPath);
  ASSERT_TRUE(file.good()) << kConfigPath;
  std::stringstream text;
  text << file.rdbuf() << "surprise_key: 1\n";
  EXPECT_THROW(loadExecutiveSettings(common::ConfigNode::loadString(text.str(), "extra.yaml")),
               common::ConfigError);
}

TEST(ExecutiveSettings, BumperBeyondVehicleLengthIsRejected)
{
  ExecutiveSettings settings;
  settings.reference_to_bumper_m = 1.5;  // the vehicle is 0.9 m long
  EXPECT_THROW(Executive(settings, common::VehicleSettings{}), std::invalid_argument);
}

}  // namespace
}  // namespace ifar::executive
