// Every namosim scenario in ../shared/data/namosim imports, each with what it holds: walls, movables,
// robots, the vehicle robot's goals, and a position worked out by hand from the file (at namosim's own
// scale, 1 unit = 1 cm: world x = 0.01 x, world y = 0.01 (viewBox height - y)).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/importers/namosim_svg_importer.hpp"

namespace ifar::sim {
namespace {

/// The walls the file draws: the importer's edge walls (edge_*) left out.
std::size_t drawnWalls(const ifar::sim::World& world)
{
  std::size_t count = 0;
  for (const auto& obstacle : world.obstacles) {
    count += obstacle.name.rfind("edge_", 0) == 0 ? 0 : 1;
  }
  return count;
}

constexpr double kPi = 3.14159265358979323846;

std::string namosimFile(const std::string& name)
{
  return std::string(IFAR_SHARED_DATA) + "/namosim/" + name;
}

NamosimImport importShared(const std::string& name, NamosimImportSettings settings = NamosimImportSettings())
{
  if (!settings.metres_per_unit) {
    settings.metres_per_unit = 0.01;
  }
  return importNamosimSvg(namosimFile(name), settings);
}

struct Scenario {
  const char* file;
  std::size_t walls;
  std::size_t movables;
  std::size_t robots;
  std::vector<std::string> goals;  // the vehicle robot's, in order
  std::size_t movable;             // the object whose pose is checked
  double movable_x;                // its centre, by hand from the path data
  double movable_y;
  bool incomplete;
};

TEST(SimWorldNamosimSharedScenarios, EveryFileImportsWithWhatItHolds)
{
  const Scenario scenarios[] = {
      // movable_box is namo:type="movable": m 57.334688,10.6531 -18.747731,0 0,18.74727 18.747731,0 z.
      {"1_robot_2_goals.svg", 2, 1, 1, {"goal_0", "goal_1"}, 0, 0.479608225, 1.27224285, false},
      // box_1: m 614.65579,576.34399 h -160 v 160 h 160 z, viewBox height 1350.
      {"1_robot_2_obstacles.svg", 4, 2, 1, {"goal_0"}, 0, 5.3465579, 6.9365601, false},
      // box_1: m 627.85883,307.42745 h -80 v 80 h 80 z, height 750 (the robot is a circle of arcs).
      {"1_robot_2_rooms.svg", 6, 1, 1, {"goal_0"}, 0, 5.8785883, 4.0257255, false},
      // movable_box: M 176.78291,44.470695 H 135.17584 V 86.10679 h 41.60707 z, height 461.7291.
      {"3_robots.svg", 3, 1, 3, {"goal_0"}, 0, 1.55979375, 3.964403575, false},
      // box_0, a rotated square of the movables_layer: the mean of its corners (126.36589, 123.20633),
      // height 242. Walls from the map_layer bitmap; no robot drawn: incomplete.
      {"citi_ing.svg", 617, 2, 1, {"goal_0"}, 0, 1.2636589, 1.1879367, true},
      // movable_box: m 1908.0228,1822.7312 h -80 v 80 h 80 z, height 3000.
      {"mapgen.svg", 3, 1, 1, {"goal_0"}, 0, 18.680228, 11.372688, false},
      // movable_box: m 63.027053,20.770784 h -15.11811 v 15.11811 h 15.11811 z, height 147.25102.
      {"minimal_stilman_2005.svg", 2, 1, 1, {"goal_0"}, 0, 0.55467998, 1.18921181, false},
      // rect54 (type="movable" inside robots_layer): m 649.15183,479.33131 h 40 v 40 h -40 z, height 1000.
      {"namoros_demo_map.svg", 5, 1, 1, {"goal_0"}, 0, 6.6915183, 5.0066869, false},
      // movable_box: M 108.15868,56.266321 H 89.410948 v 18.74727 h 18.747732 z, height 147.25102.
      {"obstacle_on_goal.svg", 2, 1, 1, {"goal_0"}, 0, 0.98784814, 0.81611064, false},
      // movable_box: m 231.74193,216.30567 h -58.74407 v 58.78505 h 58.74407 z, height 500.
      {"overlapping_movables.svg", 6, 2, 1, {"goal_0"}, 0, 2.02369895, 2.54301805, false},
      // movable_box: M 281.92137,221.08466 H 223.1773 v 58.78505 h 58.74407 z, height 500.
      {"two_rooms.svg", 4, 1, 2, {"goal_0"}, 0, 2.52549335, 2.49522815, false},
      // movable_box_13: m 79.553608,223.64854 h -40 v 40 h 40 z, height 1490.4243.
      {"willow_garage_center_small.svg", 5, 13, 1, {"goal_0"}, 12, 0.59553608, 12.4677576, false},
  };
  for (const Scenario& scenario : scenarios) {
    SCOPED_TRACE(scenario.file);
    const std::string path = namosimFile(scenario.file);
    if (!std::filesystem::exists(path)) {
      GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
    }
    const NamosimImport import = importShared(scenario.file);
    ASSERT_TRUE(import.world.ok()) << import.world.error();
    const World& world = import.world.world();
    EXPECT_EQ(drawnWalls(world), scenario.walls);
    EXPECT_EQ(world.objects.size(), scenario.movables);
    EXPECT_EQ(import.robots.size(), scenario.robots);
    ASSERT_EQ(world.goals.size(), scenario.goals.size());
    for (std::size_t index = 0; index < world.goals.size(); ++index) {
      EXPECT_EQ(world.goals[index].name, scenario.goals[index]);
    }
    ASSERT_LT(scenario.movable, world.objects.size());
    EXPECT_NEAR(world.objects[scenario.movable].pose.x, scenario.movable_x, 1e-9);
    EXPECT_NEAR(world.objects[scenario.movable].pose.y, scenario.movable_y, 1e-9);
    EXPECT_EQ(import.incomplete, scenario.incomplete);
  }
}

TEST(SimWorldNamosimSharedScenarios, RobotsDrawnWithArcsStandAtTheirCircleCentres)
{
  for (const char* file : {"1_robot_2_rooms.svg", "namoros_demo_map.svg"}) {
    if (!std::filesystem::exists(namosimFile(file))) {
      GTEST_SKIP() << "shared data file " << namosimFile(file) << " is absent; skipping real-data test";
    }
  }
  // robot_0: m 426.25863,235.62912 a 60.00001,60.000001 0 0 1 -60.00001,60 ... (four quarter arcs about
  // (366.25862, 235.62912)), in a 750-unit-high viewBox.
  const NamosimImport rooms = importShared("1_robot_2_rooms.svg");
  ASSERT_TRUE(rooms.world.ok()) << rooms.world.error();
  EXPECT_NEAR(rooms.world.world().start.x, 3.6625862, 1e-7);
  EXPECT_NEAR(rooms.world.world().start.y, 5.1437088, 1e-7);
  EXPECT_NEAR(rooms.robot_diameter_units, 120.0, 1e-4);
  // By default the robot's 120 units become the vehicle's 0.7 m.
  NamosimImportSettings vehicle_scale;
  vehicle_scale.metres_per_unit = std::nullopt;
  const NamosimImport scaled = importNamosimSvg(namosimFile("1_robot_2_rooms.svg"), vehicle_scale);
  ASSERT_TRUE(scaled.world.ok()) << scaled.world.error();
  EXPECT_NEAR(scaled.metres_per_unit, 0.7 / 120.0, 1e-9);
  // namoros_demo_map: robot_0 m 210,240 a 20,20 ... about (190, 240); goal_0 m 1294.5326,803.01042 a 30,30
  // ... about (1264.5326, 803.01042); viewBox height 1000.
  const NamosimImport demo = importShared("namoros_demo_map.svg");
  ASSERT_TRUE(demo.world.ok()) << demo.world.error();
  EXPECT_NEAR(demo.world.world().start.x, 1.9, 1e-9);
  EXPECT_NEAR(demo.world.world().start.y, 7.6, 1e-9);
  EXPECT_NEAR(demo.world.world().goals.at(0).position.x(), 12.645326, 1e-9);
  EXPECT_NEAR(demo.world.world().goals.at(0).position.y(), 1.9698958, 1e-9);
  EXPECT_NEAR(demo.robot_diameter_units, 40.0, 1e-9);
}

TEST(SimWorldNamosimSharedScenarios, SeveralRobotsEachWithTheirGoals)
{
  for (const char* file : {"3_robots.svg", "two_rooms.svg", "mapgen.svg"}) {
    if (!std::filesystem::exists(namosimFile(file))) {
      GTEST_SKIP() << "shared data file " << namosimFile(file) << " is absent; skipping real-data test";
    }
  }
  // 3_robots: the agents of namo_config each have one goal; --robot picks the vehicle by id or index.
  NamosimImportSettings third;
  third.robot = "robot_2";
  const NamosimImport robots = importShared("3_robots.svg", third);
  ASSERT_TRUE(robots.world.ok()) << robots.world.error();
  EXPECT_EQ(robots.vehicle_robot, "robot_2");
  ASSERT_EQ(robots.world.world().goals.size(), 1u);
  EXPECT_EQ(robots.world.world().goals[0].name, "goal_2");
  ASSERT_EQ(robots.warnings.size(), 2u);
  EXPECT_EQ(
      robots.warnings[0],
      "robot 'robot_0' (1 goal: goal_0) not simulated: the vehicle is robot 'robot_2' (--robot robot_0 picks "
      "it)");
  ASSERT_EQ(robots.robots.size(), 3u);
  EXPECT_EQ(robots.robots[1].goal_names, std::vector<std::string>{"goal_1"});
  // two_rooms: robot and goal groups hold robot_N_shape / robot_N_goal_0_shape and a heading mark;
  // robot_1_direction runs M 427.35348,252.82111 H 405.92697, to -x.
  NamosimImportSettings second;
  second.robot = "1";
  const NamosimImport rooms = importShared("two_rooms.svg", second);
  ASSERT_TRUE(rooms.world.ok()) << rooms.world.error();
  EXPECT_EQ(rooms.vehicle_robot, "robot_1");
  ASSERT_EQ(rooms.world.world().goals.size(), 1u);
  EXPECT_EQ(rooms.world.world().goals[0].name, "goal_1");
  EXPECT_NEAR(std::abs(rooms.world.world().start.heading), kPi, 1e-12);
  ASSERT_TRUE(rooms.robots[0].start);
  EXPECT_NEAR(rooms.robots[0].start->heading, 0.0, 1e-12);  // robot_0_direction: H to +x
  // mapgen: the same groups; robot_0_direction m 802.76082,1927.4852 h 83.9365 points to +x; every element
  // is used.
  const NamosimImport generated = importShared("mapgen.svg");
  ASSERT_TRUE(generated.world.ok()) << generated.world.error();
  EXPECT_NEAR(generated.world.world().start.heading, 0.0, 1e-12);
  EXPECT_EQ(generated.world.world().goals.at(0).name, "goal_0");
  EXPECT_TRUE(generated.warnings.empty());
}

TEST(SimWorldNamosimSharedScenarios, LayeredScenarioTakesItsWallsFromTheMapBitmap)
{
  const std::string path = namosimFile("citi_ing.svg");
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
  }
  const NamosimImport import = importShared("citi_ing.svg");
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  EXPECT_TRUE(import.incomplete);
  ASSERT_EQ(import.robots.size(), 1u);
  EXPECT_EQ(import.robots[0].id, "robot_0");  // named by goal_0's agent_id, not drawn
  EXPECT_FALSE(import.robots[0].start);
  // goal_0 is a 20-sided star about sodipodi:cx, cy = (148.11133, 145.55975).
  EXPECT_NEAR(import.world.world().goals.at(0).position.x(), 1.4811133, 1e-6);
  EXPECT_NEAR(import.world.world().goals.at(0).position.y(), 0.9644025, 1e-6);
  // The map bitmap (215 x 242 pixels drawn at 0,0 over 215 x 242 units) has unknown grey all round its
  // edge: its walls span the whole viewBox, 2.15 m x 2.42 m at 1 unit = 1 cm; the edge walls lie outside it.
  const World& world = import.world.world();
  EXPECT_EQ(world.obstacles.front().name, "image10_cells_0");
  const double edge = NamosimImportSettings().edge_wall_thickness_m;
  EXPECT_NEAR((world.bounds_min - geometry::Point(-edge, -edge)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((world.bounds_max - geometry::Point(2.15 + edge, 2.42 + edge)).norm(), 0.0, 1e-12);
  ASSERT_EQ(import.warnings.size(), 1u);
  EXPECT_EQ(import.warnings[0].rfind("robot 'robot_0' is not drawn: the start is the free spot nearest", 0),
            0u)
      << import.warnings[0];
  // Without --scale no robot gives one: namosim's centimetre, and the warning says what a unit is here.
  const NamosimImport unscaled = importNamosimSvg(path, NamosimImportSettings());
  ASSERT_TRUE(unscaled.world.ok()) << unscaled.world.error();
  EXPECT_DOUBLE_EQ(unscaled.metres_per_unit, 0.01);
  EXPECT_EQ(
      unscaled.warnings.at(0),
      "no robot drawn to take the scale from: 1 SVG unit = 1 cm, namosim's unit (--scale sets metres per "
      "unit; where a map bitmap gives the walls a unit is one of its pixels, and --scale is the map's "
      "resolution)");
}

}  // namespace
}  // namespace ifar::sim
