#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/geometry/polygon.hpp"
#include "sim/importers/namosim_svg_importer.hpp"
#include "sim/importers/svg_path.hpp"
#include "sim/world/world_geometry.hpp"

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

std::string namosimFile(const std::string& name)
{
  return std::string(IFAR_SHARED_DATA) + "/namosim/" + name;
}

TEST(SimWorldSvgPath, ParsesRelativeAndAbsoluteLineCommands)
{
  const auto parse = parseSvgPath("m 10,20 h -5 v 5 L 10 25 z M 0 0 l 1 0 0 1 Z");
  ASSERT_TRUE(parse.error.empty()) << parse.error;
  ASSERT_EQ(parse.subpaths.size(), 2u);
  const auto& first = parse.subpaths[0].points;
  ASSERT_EQ(first.size(), 4u);
  EXPECT_EQ(first[1], geometry::Point(5, 20));
  EXPECT_EQ(first[2], geometry::Point(5, 25));
  EXPECT_EQ(first[3], geometry::Point(10, 25));
  EXPECT_TRUE(parse.subpaths[0].closed);
  ASSERT_EQ(parse.subpaths[1].points.size(), 3u);  // implicit lineto after l
  EXPECT_EQ(parse.subpaths[1].points[2], geometry::Point(1, 1));
}

TEST(SimWorldSvgPath, FlattensCubicCurvesThroughTheirEndPoints)
{
  const auto parse = parseSvgPath("M 0 0 c 0,10 10,10 10,0", 4);
  ASSERT_TRUE(parse.error.empty()) << parse.error;
  const auto& points = parse.subpaths.at(0).points;
  ASSERT_EQ(points.size(), 5u);
  EXPECT_NEAR(points[2].x(), 5.0, 1e-12);
  EXPECT_NEAR(points[2].y(), 7.5, 1e-12);  // Bezier midpoint: 3/4 of the control height
  EXPECT_EQ(points[4], geometry::Point(10, 0));
}

TEST(SimWorldSvgPath, ReportsBadDataWithPosition)
{
  EXPECT_EQ(parseSvgPath("M 0 0 L 5").error, "at character 9: command 'L' expects 2 numbers");
  EXPECT_EQ(parseSvgPath("M 0 0 A 1 1 0 2 0 2 2").error,
            "at character 14: command 'A' expects flags 0 or 1 after the radii and rotation");
  EXPECT_NE(parseSvgPath("10 10").error.find("must start with a moveto"), std::string::npos);
}

TEST(SimWorldNamosimSvg, MinimalStilmanHasWallsMovableGoalAndScaledRobot)
{
  const auto path = namosimFile("minimal_stilman_2005.svg");
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
  }
  NamosimImportSettings settings;
  settings.vehicle_width_m = 0.7;
  const auto import = importNamosimSvg(path, settings);
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  const auto& world = import.world.world();
  EXPECT_EQ(drawnWalls(world), 2u);
  EXPECT_EQ(world.objects.size(), 1u);
  ASSERT_EQ(world.goals.size(), 1u);
  EXPECT_EQ(world.goals[0].name, "goal_0");
  // The robot star spans about 14.7 units; the scene is scaled so that equals the vehicle width.
  EXPECT_NEAR(import.robot_diameter_units, 14.7, 0.3);
  EXPECT_NEAR(import.robot_diameter_units * import.metres_per_unit, 0.7, 1e-12);
  // The movable box is a 15.118-unit square.
  EXPECT_NEAR(geometry::area(world.objects[0].outline), std::pow(15.11811 * import.metres_per_unit, 2), 1e-9);
  // y is flipped: the top wall (svg y 0..5.6) ends up at the top of the world.
  const auto& top = world.obstacles[0];
  EXPECT_EQ(top.name, "wall_top");
  const double height_m = 147.25102 * import.metres_per_unit;
  EXPECT_NEAR(geometry::centroid(top.outline).y(), height_m - 2.79305 * import.metres_per_unit, 1e-9);
  EXPECT_GT(world.start.y, world.goals[0].position.y())
      << "the robot is drawn near the top, the goal near the bottom";
}

TEST(SimWorldNamosimSvg, ExplicitScaleOverridesRobotScale)
{
  const auto path = namosimFile("minimal_stilman_2005.svg");
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
  }
  NamosimImportSettings settings;
  settings.metres_per_unit = 0.01;
  const auto import = importNamosimSvg(path, settings);
  ASSERT_TRUE(import.world.ok()) << import.world.error();
  EXPECT_DOUBLE_EQ(import.metres_per_unit, 0.01);
  // The viewBox is 1.5186 m wide at 1 cm per unit; the edge walls add their thickness on both sides.
  EXPECT_NEAR(import.world.world().bounds_max.x() - import.world.world().bounds_min.x(),
              1.5186 + 2.0 * settings.edge_wall_thickness_m, 1e-3);
}

TEST(SimWorldNamosimSvg, AllSharedScenariosImportWithExpectedCounts)
{
  struct Expected {
    const char* file;
    std::size_t walls;
    std::size_t movables;
    std::size_t goals;
  };
  const Expected cases[] = {{"1_robot_2_obstacles.svg", 4, 2, 1},
                            {"minimal_stilman_2005.svg", 2, 1, 1},
                            {"obstacle_on_goal.svg", 2, 1, 1},
                            {"willow_garage_center_small.svg", 5, 13, 1}};
  for (const auto& expected : cases) {
    const auto path = namosimFile(expected.file);
    if (!std::filesystem::exists(path)) {
      GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
    }
    const auto import = importNamosimSvg(path, NamosimImportSettings());
    ASSERT_TRUE(import.world.ok()) << import.world.error();
    EXPECT_EQ(drawnWalls(import.world.world()), expected.walls) << expected.file;
    EXPECT_EQ(import.world.world().objects.size(), expected.movables) << expected.file;
    EXPECT_EQ(import.world.world().goals.size(), expected.goals) << expected.file;
  }
}

std::string svgError(const std::string& body)
{
  const auto import = parseNamosimSvg(body, "bad.svg", NamosimImportSettings());
  EXPECT_FALSE(import.world.ok());
  return import.world.error();
}

const char* const kRobot = "<path id=\"robot_0\" d=\"M 1 1 h 2 v 2 h -2 z\"/>\n";

TEST(SimWorldNamosimSvg, MalformedInputNamesTheElement)
{
  EXPECT_EQ(svgError(std::string("<svg viewBox=\"0 0 10 10\">\n") + kRobot +
                     "<path id=\"w1\" type=\"wall\" d=\"M 5 5 L 8 5 L 8 8\"/>\n</svg>"),
            "bad.svg: element <path> 'w1' (line 3): open path (no closing 'z' and the end is not the start)");
  EXPECT_EQ(
      svgError(std::string("<svg viewBox=\"0 0 10 10\">\n") + kRobot +
               "<path id=\"m1\" type=\"movable\" d=\"M 5 5 Q 8 5\"/>\n</svg>"),
      "bad.svg: element <path> 'm1' (line 3): path data at character 11: command 'Q' expects 4 numbers");
  EXPECT_EQ(svgError(std::string("<svg viewBox=\"0 0 10 10\">\n") + kRobot +
                     "<path id=\"w2\" type=\"wall\" d=\"M 5 5 L 9 8 L 9 5 L 5 6 z\"/>\n</svg>"),
            "bad.svg: element <path> 'w2' (line 3): self-intersecting polygon");
  EXPECT_EQ(
      svgError(std::string("<svg viewBox=\"0 0 10 10\">\n") + kRobot +
               "<path id=\"w3\" type=\"wall\" transform=\"scale(2, 2, 2)\" d=\"M 5 5 h 1 v 1 z\"/>\n</svg>"),
      "bad.svg: element <path> 'w3' (line 3): transform: at character 0: "
      "'scale' with 3 numbers is not an SVG transform (matrix 6, translate 1-2, scale 1-2, rotate 1 or 3, "
      "skewX/skewY 1)");
  EXPECT_EQ(
      svgError(std::string("<svg viewBox=\"0 0 10 10\">\n") + kRobot +
               "<path id=\"w4\" type=\"wall\" d=\"M 5 5\n</svg>"),
      "bad.svg: malformed XML at line 3: element <path>: an attribute cannot be read (a value not quoted or "
      "not closed, or a name repeated)");
  EXPECT_EQ(svgError("<svg width=\"10\">\n</svg>"),
            "bad.svg: element <svg> (line 1): no viewBox attribute (needed to flip y)");
  EXPECT_EQ(svgError("<svg viewBox=\"0 0 10 10\">\n<g>\n</svg>"),
            "bad.svg: malformed XML at line 2: element <g>: not closed by its own end tag");
}

TEST(SimWorldNamosimSvg, MovableInsideWallIsRejectedAfterConversion)
{
  const std::string svg = std::string("<svg viewBox=\"0 0 100 100\">\n") + kRobot +
                          "<path id=\"block\" type=\"wall\" d=\"M 50 50 h 20 v 20 h -20 z\"/>\n"
                          "<path id=\"crate\" type=\"movable\" d=\"M 55 55 h 5 v 5 h -5 z\"/>\n</svg>";
  EXPECT_EQ(svgError(svg), "bad.svg: object 'crate' (id 1): overlaps obstacle 'block'");
}

}  // namespace
}  // namespace ifar::sim
