// namosim's scenario conventions on small SVGs written for the test: robots and goals by namo_config, by
// layers and by names, several robots, the vehicle robot chosen, warnings for what is not used, paths closed
// within rounding, transformed groups, and worlds without walls, robot or goals.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "common/geometry/polygon.hpp"
#include "sim/importers/namosim_svg_importer.hpp"
#include "sim/importers/svg_map_image.hpp"

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

using geometry::Point;

constexpr double kPi = 3.14159265358979323846;

/// A 1000 x 1000 unit drawing (10 m at namosim's centimetre) around `body`.
std::string drawing(const std::string& body)
{
  return "<svg viewBox=\"0 0 1000 1000\" xmlns:namo=\"namo\">\n" + body + "</svg>\n";
}

const char* const kWalls =
    "<path id=\"outer\" type=\"wall\" d=\"M 0 0 H 1000 V 20 H 0 Z\"/>\n"
    "<path id=\"inner\" type=\"wall\" d=\"M 400 400 h 200 v 200 h -200 z\"/>\n";

NamosimImportSettings trueSize()
{
  NamosimImportSettings settings;
  settings.metres_per_unit = 0.01;
  return settings;
}

NamosimImport importText(const std::string& text, const NamosimImportSettings& settings = trueSize())
{
  return parseNamosimSvg(text, "test.svg", settings);
}

bool hasWarning(const NamosimImport& import, const std::string& text)
{
  return std::any_of(import.warnings.begin(), import.warnings.end(),
                     [&text](const std::string& warning) { return warning == text; });
}

std::string allWarnings(const NamosimImport& import)
{
  std::string all;
  for (const auto& warning : import.warnings) {
    all += "\n  " + warning;
  }
  return all;
}

/// A square marker of side 20 centred on (x, y) in SVG units.
std::string marker(const std::string& id, double x, double y, const std::string& extra = "")
{
  return "<path id=\"" + id + "\" " + extra + " d=\"M " + std::to_string(x - 10) + " " +
         std::to_string(y - 10) + " h 20 v 20 h -20 z\"/>\n";
}

TEST(SimWorldNamosimConventions, RobotGoalIdsGiveEachRobotItsGoalSequence)
{
  // No namo_config: robot_N and robot_N_goal_M by their names, goals in the order of M whatever the
  // document order.
  const std::string svg = drawing(std::string(kWalls) + marker("robot_0", 100, 900) +
                                  marker("robot_1", 900, 900) + marker("robot_0_goal_1", 100, 100) +
                                  marker("robot_1_goal_0", 900, 100) + marker("robot_0_goal_0", 300, 700));
  const NamosimImport import = importText(svg);
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  const World& world = import.world.world();
  EXPECT_EQ(import.vehicle_robot, "robot_0");
  ASSERT_EQ(world.goals.size(), 2u);
  EXPECT_EQ(world.goals[0].name, "robot_0_goal_0");
  EXPECT_NEAR(world.goals[0].position.x(), 3.0, 1e-12);  // (300 - 0) x 0.01
  EXPECT_NEAR(world.goals[0].position.y(), 3.0, 1e-12);  // (1000 - 700) x 0.01
  EXPECT_EQ(world.goals[1].name, "robot_0_goal_1");
  EXPECT_NEAR(world.goals[1].position.y(), 9.0, 1e-12);
  EXPECT_NEAR(world.start.x, 1.0, 1e-12);
  EXPECT_NEAR(world.start.y, 1.0, 1e-12);
  EXPECT_FALSE(import.incomplete);
  EXPECT_TRUE(hasWarning(import,
                         "robot 'robot_1' (1 goal: robot_1_goal_0) not simulated: the vehicle is robot "
                         "'robot_0' (--robot robot_1 picks it)"))
      << allWarnings(import);
  ASSERT_EQ(import.robots.size(), 2u);
  ASSERT_EQ(import.robots[1].goals.size(), 1u);
  EXPECT_NEAR(import.robots[1].goals[0].x(), 9.0, 1e-12);

  // --robot by index and by id picks the other robot and its goals.
  for (const std::string& choice : {std::string("1"), std::string("robot_1")}) {
    NamosimImportSettings settings = trueSize();
    settings.robot = choice;
    const NamosimImport second = importText(svg, settings);
    ASSERT_TRUE(second.world.ok()) << second.world.error();
    EXPECT_EQ(second.vehicle_robot, "robot_1");
    ASSERT_EQ(second.world.world().goals.size(), 1u);
    EXPECT_EQ(second.world.world().goals[0].name, "robot_1_goal_0");
    EXPECT_NEAR(second.world.world().start.x, 9.0, 1e-12);
    EXPECT_TRUE(hasWarning(second,
                           "robot 'robot_0' (2 goals: robot_0_goal_0, robot_0_goal_1) not simulated: the "
                           "vehicle is robot 'robot_1' (--robot robot_0 picks it)"))
        << allWarnings(second);
  }
  NamosimImportSettings missing = trueSize();
  missing.robot = "robot_7";
  EXPECT_EQ(importText(svg, missing).world.error(),
            "test.svg: no robot 'robot_7' (by id or index) in the file; its robots: robot_0, robot_1");
}

TEST(SimWorldNamosimConventions, NamoConfigAgentsWithGroupsHeadingsAndMissingElements)
{
  // As two_rooms.svg and mapgen.svg: each robot and goal a group of a shape and an orientation mark, the
  // agents' goal lists in namo_config.
  const std::string svg = drawing(
      std::string("<namo_config cell_size_cm=\"5\">\n"
                  "<agent agent_id=\"robot_0\"><goal goal_id=\"goal_0\"/><goal goal_id=\"goal_9\"/>"
                  "<behavior type=\"stilman_2005_behavior\"/></agent>\n"
                  "<agent agent_id=\"robot_1\"><goal goal_id=\"goal_1\"/></agent>\n"
                  "<agent agent_id=\"robot_2\"/>\n</namo_config>\n") +
      kWalls +
      "<g id=\"robot_0\"><path id=\"robot_0_shape\" type=\"shape\" d=\"M 90 890 h 20 v 20 h -20 z\"/>"
      "<path id=\"robot_0_direction\" type=\"orientation\" d=\"M 100 900 h -10\"/></g>\n"
      "<g id=\"goal_0\"><path id=\"robot_0_goal_0_shape\" type=\"shape\" d=\"M 190 190 h 20 v 20 h -20 z\"/>"
      "<path id=\"robot_0_goal_0_direction\" type=\"orientation\" d=\"M 200 200 v -10\"/></g>\n" +
      marker("robot_1", 800, 800, "type=\"shape\" angle=\"90\"") +
      marker("goal_1", 800, 200, "type=\"shape\"") + marker("goal_5", 500, 900, "type=\"shape\""));
  const NamosimImport import = importText(svg);
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  const World& world = import.world.world();
  EXPECT_NEAR(world.start.x, 1.0, 1e-12);
  EXPECT_NEAR(world.start.y, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(world.start.heading), kPi, 1e-12) << "the orientation mark points to -x";
  ASSERT_EQ(world.goals.size(), 1u);
  EXPECT_EQ(world.goals[0].name, "goal_0");
  EXPECT_NEAR(world.goals[0].position.x(), 2.0, 1e-12);
  EXPECT_NEAR(world.goals[0].position.y(), 8.0, 1e-12);
  ASSERT_EQ(import.robots.size(), 3u);
  ASSERT_TRUE(import.robots[1].start);
  EXPECT_NEAR(import.robots[1].start->heading, 0.5 * kPi, 1e-12) << "angle=\"90\": degrees counter-clockwise";
  EXPECT_FALSE(import.robots[2].start) << "robot_2 is listed but not drawn";
  EXPECT_TRUE(hasWarning(import,
                         "goal 'goal_9' of agent 'robot_0' in <namo_config> has no element with that id: "
                         "not used"))
      << allWarnings(import);
  EXPECT_TRUE(hasWarning(import,
                         "agent 'robot_2' of <namo_config> has no element with that id: the file does "
                         "not say where it starts"))
      << allWarnings(import);
  EXPECT_TRUE(hasWarning(import,
                         "element <path> 'goal_5' (line 13) looks like a robot or goal, but no agent of "
                         "<namo_config> lists it: not used"))
      << allWarnings(import);
  EXPECT_TRUE(hasWarning(import,
                         "robot 'robot_1' (1 goal: goal_1) not simulated: the vehicle is robot 'robot_0' "
                         "(--robot robot_1 picks it)"))
      << allWarnings(import);
  EXPECT_TRUE(hasWarning(import,
                         "robot 'robot_2' (no goals) not simulated: the vehicle is robot 'robot_0' "
                         "(--robot robot_2 picks it)"))
      << allWarnings(import);
  EXPECT_EQ(import.warnings.size(), 5u) << allWarnings(import);
}

TEST(SimWorldNamosimConventions, LayersOfARosMapScenario)
{
  // As citi_ing.svg, plus a robot: every element of movables_layer is a movable, goals name their robot.
  const std::string svg = drawing(
      std::string(kWalls) +
      "<g id=\"movables_layer\"><path id=\"box_0\" d=\"M 700 700 h 40 v 40 h -40 z\"/>"
      "<rect id=\"box_1\" x=\"700\" y=\"100\" width=\"50\" height=\"30\"/></g>\n"
      "<g id=\"robots_layer\"><path id=\"r\" agent_id=\"robot_0\" d=\"M 90 90 h 20 v 20 h -20 z\"/></g>\n"
      "<g id=\"goals_layer\"><path id=\"g_b\" agent_id=\"robot_0\" d=\"M 290 290 h 20 v 20 h -20 z\"/>"
      "<path id=\"g_a\" agent_id=\"robot_0\" d=\"M 890 890 h 20 v 20 h -20 z\"/></g>\n");
  const NamosimImport import = importText(svg);
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  const World& world = import.world.world();
  ASSERT_EQ(world.objects.size(), 2u);
  EXPECT_EQ(world.objects[1].name, "box_1");
  EXPECT_NEAR(world.objects[1].pose.x, 7.25, 1e-12);
  EXPECT_NEAR(world.objects[1].pose.y, 8.85, 1e-12);  // (1000 - 115) x 0.01
  ASSERT_EQ(world.goals.size(), 2u);
  EXPECT_EQ(world.goals[0].name, "g_b");  // document order
  EXPECT_EQ(world.goals[1].name, "g_a");
  EXPECT_NEAR(world.start.y, 9.0, 1e-12);
  EXPECT_TRUE(import.warnings.empty()) << allWarnings(import);
}

// A 4 x 3 grey PNG: row 0 = 255 0 255 255, row 1 = 255 0 205 255, row 2 all 255 (0 is occupied, 205 is
// map_server's unknown: occupancy 0.196 is not below the free threshold).
const char* const kMapPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAQAAAADCAAAAACRn/EaAAAAE0lEQVR4nGP4z/AfiBjOguj//"
    "wFDbAnFKL1LbQAAAABJRU5ErkJggg==";

TEST(SimWorldNamosimConventions, MapLayerBitmapBecomesWallsAndMovablesClearTheirCells)
{
  // Drawn at (100, 200), 10 units a pixel: blocked cells (1,0), (1,1) and unknown (2,1).
  const auto scenario = [](const std::string& movables) {
    return drawing(
        "<g id=\"map_layer\"><image id=\"map\" x=\"100\" y=\"200\" width=\"40\" height=\"30\" "
        "preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64," +
        std::string(kMapPng) + "\"/></g>\n<g id=\"movables_layer\">" + movables + "</g>\n" +
        marker("robot_0", 100, 900) + marker("goal_0", 900, 900));
  };
  const NamosimImport bare = importText(scenario(""));
  ASSERT_TRUE(bare.world.ok()) << bare.world.error();
  const World& walls = bare.world.world();
  ASSERT_EQ(drawnWalls(walls), 2u);
  EXPECT_EQ(walls.obstacles[0].name, "map_cells_0");
  // Cell (1,0): x 110..120, y 200..210 in the file; y flips to 7.9..8.0 m.
  const Eigen::AlignedBox2d first = geometry::boundingBox(walls.obstacles[0].outline);
  EXPECT_NEAR((first.min() - Point(1.1, 7.9)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((first.max() - Point(1.2, 8.0)).norm(), 0.0, 1e-12);
  // Cells (1,1) and (2,1): x 110..130, y 210..220.
  const Eigen::AlignedBox2d second = geometry::boundingBox(walls.obstacles[1].outline);
  EXPECT_NEAR((second.min() - Point(1.1, 7.8)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((second.max() - Point(1.3, 7.9)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(bare.incomplete) << allWarnings(bare);
  // A movable standing on cell (2,1) frees it: one wall of cells (1,0) and (1,1) is left, and no overlap.
  const NamosimImport boxed =
      importText(scenario("<rect id=\"crate\" x=\"121\" y=\"211\" width=\"8\" height=\"8\"/>"));
  ASSERT_TRUE(boxed.world.ok()) << boxed.world.error();
  ASSERT_EQ(drawnWalls(boxed.world.world()), 1u);
  const Eigen::AlignedBox2d merged = geometry::boundingBox(boxed.world.world().obstacles[0].outline);
  EXPECT_NEAR((merged.min() - Point(1.1, 7.8)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((merged.max() - Point(1.2, 8.0)).norm(), 0.0, 1e-12);
  ASSERT_EQ(boxed.world.world().objects.size(), 1u);
  // A bitmap that is not a PNG data URI is named in a warning.
  const NamosimImport linked =
      importText(drawing(std::string(kWalls) + marker("robot_0", 100, 900) + marker("goal_0", 900, 900) +
                         "<g id=\"map_layer\"><image href=\"map.pgm\"/></g>\n"));
  ASSERT_TRUE(linked.world.ok()) << linked.world.error();
  EXPECT_TRUE(hasWarning(linked,
                         "element <image> (line 6): map_layer image not read: only PNG data URIs "
                         "(data:image/png;base64,...) are read, not 'map.pgm'"))
      << allWarnings(linked);
}

TEST(SimWorldNamosimConventions, Base64DecodesAndRefusesOtherCharacters)
{
  EXPECT_EQ(decodeBase64("TWFu"), "Man");
  EXPECT_EQ(decodeBase64(" TW\nE= "), "Ma");
  EXPECT_EQ(decodeBase64("TQ=="), "M");
  EXPECT_FALSE(decodeBase64("TW*u"));
  EXPECT_FALSE(decodeBase64("TQ==TQ"));
}

TEST(SimWorldNamosimConventions, NamespacedTypeCountsButInkscapeTypesDoNot)
{
  const std::string svg =
      drawing(std::string(kWalls) + marker("robot_0", 100, 900, "sodipodi:type=\"star\"") +
              marker("goal_0", 900, 900) +
              "<path id=\"crate\" namo:type=\"movable\" d=\"M 700 700 h 40 v 40 h -40 z\"/>\n");
  const NamosimImport import = importText(svg);
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  ASSERT_EQ(import.world.world().objects.size(), 1u);
  EXPECT_EQ(import.world.world().objects[0].name, "crate");
  EXPECT_EQ(drawnWalls(import.world.world()), 2u);
  EXPECT_EQ(import.vehicle_robot, "robot_0");
}

TEST(SimWorldNamosimConventions, OpenPathWithinRoundingIsClosed)
{
  // The closing tolerance is 1e-5 of the viewBox's larger side: 0.01 units here. Ends 0.005 apart close
  // the outline (4 vertices, not 5); ends 2 units apart are a path that is really open.
  const auto wall = [](const std::string& last_point) {
    return drawing(marker("robot_0", 100, 900) + marker("goal_0", 900, 900) +
                   "<path id=\"rounded\" type=\"wall\" d=\"M 100 100 L 300 100 L 300 300 L 100 300 L " +
                   last_point + "\"/>\n");
  };
  const NamosimImport closed = importText(wall("100.004 100.003"));
  ASSERT_TRUE(closed.world.ok()) << closed.world.error();
  ASSERT_EQ(drawnWalls(closed.world.world()), 1u);
  EXPECT_EQ(closed.world.world().obstacles[0].outline.size(), 4u);
  EXPECT_NEAR(geometry::area(closed.world.world().obstacles[0].outline), 4.0, 1e-6);
  EXPECT_EQ(
      importText(wall("100 102")).world.error(),
      "test.svg: element <path> 'rounded' (line 4): open path (no closing 'z' and the end is not the start)");
}

TEST(SimWorldNamosimConventions, TransformedGroupMatchesTheWorldWrittenWithoutIt)
{
  // The same scene twice: once inside nested transformed groups, once with every point mapped by hand
  // (translate(100, 50) rotate(90) scale(2), then the inner translate(10, 0)): (x, y) -> (100 - 2y, 50 + 2(x
  // + 10)).
  const std::string transformed = drawing(
      "<g transform=\"translate(100, 50) rotate(90) scale(2)\">\n"
      "<path id=\"wall\" type=\"wall\" transform=\"translate(10 0)\" d=\"M 0 -10 h 100 v 5 h -100 z\"/>\n"
      "<rect id=\"box\" type=\"movable\" x=\"40\" y=\"-40\" width=\"10\" height=\"10\"/>\n"
      "<circle id=\"robot_0\" cx=\"10\" cy=\"-30\" r=\"5\"/>\n"
      "<path id=\"goal_0\" d=\"M 140 -35 h 10 v 10 h -10 z\"/>\n</g>\n");
  const std::string by_hand = drawing(
      "<path id=\"wall\" type=\"wall\" d=\"M 120 70 V 270 H 110 V 70 z\"/>\n"
      "<path id=\"box\" type=\"movable\" d=\"M 180 130 V 150 H 160 V 130 z\"/>\n"
      "<circle id=\"robot_0\" cx=\"160\" cy=\"70\" r=\"10\"/>\n"
      "<path id=\"goal_0\" d=\"M 170 330 V 350 H 150 V 330 z\"/>\n");
  NamosimImportSettings settings;  // the robot sets the scale: its size must match too
  const NamosimImport first = importText(transformed, settings);
  const NamosimImport second = importText(by_hand, settings);
  ASSERT_TRUE(first.world.ok()) << first.world.error();
  ASSERT_TRUE(second.world.ok()) << second.world.error();
  EXPECT_NEAR(first.metres_per_unit, 0.7 / 20.0, 1e-12);
  EXPECT_NEAR(first.metres_per_unit, second.metres_per_unit, 1e-12);
  const World& a = first.world.world();
  const World& b = second.world.world();
  EXPECT_NEAR(a.start.x, b.start.x, 1e-9);
  EXPECT_NEAR(a.start.y, b.start.y, 1e-9);
  ASSERT_EQ(a.goals.size(), 1u);
  ASSERT_EQ(b.goals.size(), 1u);
  EXPECT_NEAR((a.goals[0].position - b.goals[0].position).norm(), 0.0, 1e-9);
  ASSERT_EQ(a.objects.size(), 1u);
  ASSERT_EQ(b.objects.size(), 1u);
  EXPECT_NEAR(a.objects[0].pose.x, b.objects[0].pose.x, 1e-9);
  EXPECT_NEAR(a.objects[0].pose.y, b.objects[0].pose.y, 1e-9);
  EXPECT_NEAR(geometry::area(a.objects[0].outline), geometry::area(b.objects[0].outline), 1e-9);
  ASSERT_EQ(drawnWalls(a), 1u);
  ASSERT_EQ(drawnWalls(b), 1u);
  ASSERT_EQ(a.obstacles[0].outline.size(), b.obstacles[0].outline.size());
  const auto low = [](const geometry::Polygon& polygon) { return geometry::boundingBox(polygon).min(); };
  EXPECT_NEAR((low(a.obstacles[0].outline) - low(b.obstacles[0].outline)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(geometry::area(a.obstacles[0].outline), geometry::area(b.obstacles[0].outline), 1e-9);
}

TEST(SimWorldNamosimConventions, MissingWallsRobotOrGoalsMakeAnIncompleteWorld)
{
  // Walls and goals but no robot: the start is the free spot nearest the viewBox's centre (the centre is in
  // the 2 m block 'inner'; on the grid of 0.35 m steps from (0, 0) the nearest point clear of it by half the
  // vehicle's width is (3.5, 4.9), the first in grid order of four as near), and the world is incomplete.
  const NamosimImport no_robot = importText(drawing(std::string(kWalls) + marker("goal_0", 900, 900)));
  ASSERT_TRUE(no_robot.world.ok()) << no_robot.world.error();
  EXPECT_TRUE(no_robot.incomplete);
  EXPECT_NEAR(no_robot.world.world().start.x, 3.5, 1e-9);
  EXPECT_NEAR(no_robot.world.world().start.y, 4.9, 1e-9);
  EXPECT_TRUE(hasWarning(no_robot,
                         "robot 'robot_0' is not drawn: the start is the free spot nearest the centre "
                         "of the viewBox, (3.500000, 4.900000) m; give one with --start"))
      << allWarnings(no_robot);
  // A start from the command line completes it.
  NamosimImportSettings with_start = trueSize();
  with_start.start = geometry::Pose2{2.0, 8.0, 0.5};
  const NamosimImport started =
      importText(drawing(std::string(kWalls) + marker("goal_0", 900, 900)), with_start);
  ASSERT_TRUE(started.world.ok()) << started.world.error();
  EXPECT_FALSE(started.incomplete) << allWarnings(started);
  EXPECT_DOUBLE_EQ(started.world.world().start.y, 8.0);
  // No walls, no goals: one warning each.
  const NamosimImport empty = importText(drawing(marker("robot_0", 100, 900)));
  ASSERT_TRUE(empty.world.ok()) << empty.world.error();
  EXPECT_TRUE(empty.incomplete);
  EXPECT_TRUE(
      hasWarning(empty, "no walls: no drawing element has type=\"wall\" and no map_layer bitmap holds any"))
      << allWarnings(empty);
  EXPECT_TRUE(hasWarning(empty, "no goals: robot 'robot_0' has none")) << allWarnings(empty);
  // Nothing at all: no robot to scale by either.
  const NamosimImport nothing = parseNamosimSvg(drawing(""), "test.svg", NamosimImportSettings());
  ASSERT_TRUE(nothing.world.ok()) << nothing.world.error();
  EXPECT_TRUE(nothing.incomplete);
  EXPECT_DOUBLE_EQ(nothing.metres_per_unit, 0.01);
  EXPECT_TRUE(hasWarning(nothing, "no goals: the file has no robot and no goal")) << allWarnings(nothing);
  EXPECT_TRUE(hasWarning(nothing,
                         "no robot drawn to take the scale from: 1 SVG unit = 1 cm, namosim's unit "
                         "(--scale sets metres per unit)"))
      << allWarnings(nothing);
}

// namosim's grid ends at the document's extent: four walls just outside the viewBox close the world, so
// the vehicle cannot drive round the drawing's open side; with the thickness at 0 there are none.
TEST(SimWorldNamosimConventions, TheViewBoxEdgeClosesTheWorld)
{
  const NamosimImport closed = importText(drawing(kWalls));
  ASSERT_TRUE(closed.world.ok()) << closed.world.error();
  const World& world = closed.world.world();
  ASSERT_EQ(world.obstacles.size(), 6u);
  const double edge = trueSize().edge_wall_thickness_m;
  ASSERT_GT(edge, 0.0);
  const char* const names[] = {"edge_south", "edge_east", "edge_north", "edge_west"};
  const Eigen::AlignedBox2d expected[] = {
      {geometry::Point(-edge, -edge), geometry::Point(10.0 + edge, 0.0)},
      {geometry::Point(10.0, 0.0), geometry::Point(10.0 + edge, 10.0)},
      {geometry::Point(-edge, 10.0), geometry::Point(10.0 + edge, 10.0 + edge)},
      {geometry::Point(-edge, 0.0), geometry::Point(0.0, 10.0)},
  };
  for (std::size_t side = 0; side < 4; ++side) {
    const auto& obstacle = world.obstacles[2 + side];
    EXPECT_EQ(obstacle.name, names[side]);
    const Eigen::AlignedBox2d box = geometry::boundingBox(obstacle.outline);
    EXPECT_NEAR((box.min() - expected[side].min()).norm(), 0.0, 1e-9) << names[side];
    EXPECT_NEAR((box.max() - expected[side].max()).norm(), 0.0, 1e-9) << names[side];
    EXPECT_NEAR(geometry::area(obstacle.outline), expected[side].volume(), 1e-9) << names[side];
  }

  NamosimImportSettings open = trueSize();
  open.edge_wall_thickness_m = 0.0;
  const NamosimImport without = importText(drawing(kWalls), open);
  ASSERT_TRUE(without.world.ok()) << without.world.error();
  EXPECT_EQ(without.world.world().obstacles.size(), 2u);
}

}  // namespace
}  // namespace ifar::sim
