#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sim/world/world_file.hpp"
#include "world_test_fixtures.hpp"

namespace ifar::sim {
namespace {

void expectSameWorld(const World& expected, const World& actual)
{
  EXPECT_EQ(actual.name, expected.name);
  ASSERT_EQ(actual.obstacles.size(), expected.obstacles.size());
  for (std::size_t i = 0; i < expected.obstacles.size(); ++i) {
    EXPECT_EQ(actual.obstacles[i].name, expected.obstacles[i].name);
    EXPECT_EQ(actual.obstacles[i].outline, expected.obstacles[i].outline);
    EXPECT_EQ(actual.obstacles[i].height_m, expected.obstacles[i].height_m);
    EXPECT_EQ(actual.obstacles[i].reflectivity, expected.obstacles[i].reflectivity);
  }
  ASSERT_EQ(actual.objects.size(), expected.objects.size());
  for (std::size_t i = 0; i < expected.objects.size(); ++i) {
    const auto& a = actual.objects[i];
    const auto& e = expected.objects[i];
    EXPECT_EQ(a.id, e.id);
    EXPECT_EQ(a.name, e.name);
    EXPECT_EQ(a.outline, e.outline);
    EXPECT_EQ(a.pose.x, e.pose.x);
    EXPECT_EQ(a.pose.y, e.pose.y);
    EXPECT_NEAR(a.pose.heading, e.pose.heading, 1e-12);  // stored in degrees to 12 digits
    EXPECT_EQ(a.mass_kg, e.mass_kg);
    EXPECT_EQ(a.ground_friction, e.ground_friction);
    EXPECT_EQ(a.reflectivity, e.reflectivity);
    EXPECT_EQ(a.height_m, e.height_m);
  }
  EXPECT_EQ(actual.start.x, expected.start.x);
  EXPECT_EQ(actual.start.y, expected.start.y);
  EXPECT_NEAR(actual.start.heading, expected.start.heading, 1e-12);
  ASSERT_EQ(actual.goals.size(), expected.goals.size());
  for (std::size_t i = 0; i < expected.goals.size(); ++i) {
    EXPECT_EQ(actual.goals[i].name, expected.goals[i].name);
    EXPECT_EQ(actual.goals[i].position, expected.goals[i].position);
  }
  EXPECT_LT((actual.bounds_min - expected.bounds_min).norm(), 1e-9);
  EXPECT_LT((actual.bounds_max - expected.bounds_max).norm(), 1e-9);
}

TEST(SimWorldFile, SaveLoadRoundTripReproducesTheWorld)
{
  const World world = testing::smallRoom();
  const auto path = std::filesystem::temp_directory_path() / "ifar_world_round_trip.yaml";
  ASSERT_EQ(saveWorldFile(world, path.string()), "");
  const auto loaded = loadWorldFile(path.string());
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  expectSameWorld(world, loaded.world());
  EXPECT_EQ(loaded.world().source, path.string());
  // Saving again gives the same text.
  EXPECT_EQ(formatWorld(loaded.world()), formatWorld(world));
  std::filesystem::remove(path);
}

TEST(SimWorldFile, ReadsDocumentedFormatWithDefaultsAndUnits)
{
  const auto result = parseWorld(R"(
name: tiny
units: cm
start: {x: 100, y: 100}
goals:
  - {x: 300, y: 50}
obstacles:
  - name: block
    polygon: [200, 0,  200, 20,  220, 20,  220, 0]   # clockwise on purpose
objects:
  - id: 3
    pose: {x: 300, y: 150, heading_deg: 90}
    polygon: [0, 0,  40, 0,  40, 20,  0, 20]          # body frame not centred
    mass_kg: 12
)",
                                 "tiny.yaml");
  ASSERT_TRUE(result.ok()) << result.error();
  const auto& world = result.world();
  EXPECT_DOUBLE_EQ(world.start.x, 1.0);
  EXPECT_DOUBLE_EQ(world.start.heading, 0.0);
  EXPECT_EQ(world.goals.at(0).name, "goal_0");
  EXPECT_DOUBLE_EQ(world.goals.at(0).position.x(), 3.0);
  const auto& block = world.obstacles.at(0);
  EXPECT_GT(geometry::signedArea(block.outline), 0.0) << "outline made counter-clockwise";
  EXPECT_DOUBLE_EQ(block.height_m, 2.0);
  EXPECT_DOUBLE_EQ(block.reflectivity, 0.2);
  const auto& object = world.objects.at(0);
  EXPECT_EQ(object.name, "object_3");
  EXPECT_DOUBLE_EQ(object.ground_friction, 0.5);
  EXPECT_DOUBLE_EQ(object.height_m, 1.0);
  // Body frame moved to the centroid (0.2, 0.1), which rotated by 90 degrees lands at (3 - 0.1, 1.5 + 0.2).
  EXPECT_NEAR(geometry::centroid(object.outline).norm(), 0.0, 1e-12);
  EXPECT_NEAR(object.pose.x, 2.9, 1e-12);
  EXPECT_NEAR(object.pose.y, 1.7, 1e-12);
  EXPECT_NEAR(world.bounds_max.x(), 3.0, 1e-12);  // 0.2 m deep box turned upright
}

TEST(SimWorldFile, MissingFileIsReportedWithItsPath)
{
  const auto result = loadWorldFile("/nonexistent/world.yaml");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "/nonexistent/world.yaml: cannot open world file");
}

}  // namespace
}  // namespace ifar::sim
