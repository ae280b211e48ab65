#include <gtest/gtest.h>

#include "sim/world/world_file.hpp"
#include "sim/world/world_validation.hpp"
#include "world_test_fixtures.hpp"

namespace ifar::sim {
namespace {

const char* const kHeader = "name: bad\nunits: m\nstart: {x: 1, y: 1}\ngoals: []\n";

std::string errorFor(const std::string& body)
{
  const auto result = parseWorld(std::string(kHeader) + body, "bad.yaml");
  EXPECT_FALSE(result.ok());
  return result.error();
}

TEST(SimWorldValidation, SmallRoomIsValid)
{
  EXPECT_TRUE(findWorldProblems(testing::smallRoom()).empty());
}

TEST(SimWorldValidation, SelfIntersectingPolygonNamesFileEntityAndProblem)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: bowtie\n    polygon: [3, 0,  6, 3,  6, 0,  3, 1]\n"),
            "bad.yaml: obstacle 'bowtie': self-intersecting polygon");
}

TEST(SimWorldValidation, AbsurdExtentsAndHeadingsAreRefusedNamingTheEntity)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: long wall\n    polygon: [0, 0,  1e9, 0,  1e9, 0.2,  0, 0.2]\n"),
            "bad.yaml: obstacle 'long wall': polygon reaches beyond 100000 m of the origin");
  EXPECT_EQ(errorFor("objects:\n  - {id: 1, name: box, mass_kg: 10, polygon: [0, 0, 1, 0, 1, 1, 0, 1],\n"
                     "     pose: {x: 5, y: 5, heading_deg: 1e300}}\n"),
            "bad.yaml: object 'box' (id 1): heading is more than ten turns (3600 degrees) either way");
  const auto far_start = parseWorld("name: far\nunits: m\nstart: {x: 2e5, y: 1}\ngoals: []\n", "far.yaml");
  ASSERT_FALSE(far_start.ok());
  EXPECT_EQ(far_start.error(), "far.yaml: start: pose lies beyond 100000 m of the origin");
  const auto far_goal =
      parseWorld("name: far\nunits: m\nstart: {x: 1, y: 1}\ngoals: [{x: 1, y: -3e5}]\n", "goal.yaml");
  ASSERT_FALSE(far_goal.ok());
  EXPECT_EQ(far_goal.error(), "goal.yaml: goal 'goal_0': position lies beyond 100000 m of the origin");
}

TEST(SimWorldValidation, OpenPolygonIsRejected)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: stub\n    polygon: [3, 0,  5, 2]\n"),
            "bad.yaml: obstacle 'stub': open or degenerate polygon: 2 vertices, at least 3 needed");
}

TEST(SimWorldValidation, ZeroAreaPolygonIsRejected)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: line\n    polygon: [3, 0,  4, 0,  5, 0]\n"),
            "bad.yaml: obstacle 'line': degenerate polygon: zero area");
}

TEST(SimWorldValidation, OddCoordinateCountIsRejected)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: odd\n    polygon: [3, 0,  4, 0,  5]\n"),
            "bad.yaml: key 'obstacles[0].polygon': needs x, y pairs, got an odd count of 5 numbers");
}

TEST(SimWorldValidation, ObjectInsideWallIsRejected)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: wall\n    polygon: [3, 0,  6, 0,  6, 3,  3, 3]\n"
                     "objects:\n  - id: 2\n    name: crate\n    pose: {x: 3, y: 1.5}\n"
                     "    polygon: [-0.5, -0.5,  0.5, -0.5,  0.5, 0.5,  -0.5, 0.5]\n    mass_kg: 10\n"),
            "bad.yaml: object 'crate' (id 2): overlaps obstacle 'wall'");
}

TEST(SimWorldValidation, ObjectTouchingWallIsAllowed)
{
  const auto result =
      parseWorld(std::string(kHeader) +
                     "obstacles:\n  - name: wall\n    polygon: [3, 0,  6, 0,  6, 3,  3, 3]\n"
                     "objects:\n  - id: 2\n    pose: {x: 2.5, y: 1.5}\n"
                     "    polygon: [-0.5, -0.5,  0.5, -0.5,  0.5, 0.5,  -0.5, 0.5]\n    mass_kg: 10\n",
                 "ok.yaml");
  EXPECT_TRUE(result.ok()) << result.error();
}

TEST(SimWorldValidation, StartInsideObstacleIsRejected)
{
  EXPECT_EQ(errorFor("obstacles:\n  - name: pillar\n    polygon: [0, 0,  2, 0,  2, 2,  0, 2]\n"),
            "bad.yaml: start: lies inside obstacle 'pillar'");
}

TEST(SimWorldValidation, NegativeMassIsRejected)
{
  EXPECT_EQ(errorFor("objects:\n  - id: 4\n    name: ghost\n    pose: {x: 5, y: 5}\n"
                     "    polygon: [-0.5, -0.5,  0.5, -0.5,  0.5, 0.5,  -0.5, 0.5]\n    mass_kg: -3\n"),
            "bad.yaml: object 'ghost' (id 4): mass must be positive, got -3.000000 kg");
}

TEST(SimWorldValidation, UnknownKeyIsRejected)
{
  const auto error =
      errorFor("obstacles:\n  - name: wall\n    colour: red\n    polygon: [3, 0,  6, 0,  6, 3]\n");
  EXPECT_NE(error.find("bad.yaml"), std::string::npos) << error;
  EXPECT_NE(error.find("obstacles[0].colour"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown key"), std::string::npos) << error;
}

TEST(SimWorldValidation, UnknownUnitsAreRejected)
{
  const auto result = parseWorld("name: bad\nunits: furlong\nstart: {x: 1, y: 1}\n", "bad.yaml");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "bad.yaml: key 'units': unknown units 'furlong' (expected m, cm or mm)");
}

TEST(SimWorldValidation, DuplicateIdsAndOverlappingObjectsAreReported)
{
  World world = testing::smallRoom();
  world.objects.push_back(world.objects.front());
  world.objects.back().name = "twin";
  const auto problems = findWorldProblems(world);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].entity, "object 'twin' (id 7)");
  EXPECT_EQ(problems[0].problem, "id is already used by object 'box_7'");

  world.objects.back().id = 8;
  const auto overlaps = findWorldProblems(world);
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(overlaps[0].problem, "overlaps object 'twin' (id 8)");
}

TEST(SimWorldValidation, GoalInsideWallIsRejected)
{
  World world = testing::smallRoom();
  world.goals.push_back({"buried", geometry::Point(5.5, 3.3)});
  const auto problems = findWorldProblems(world);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(describeProblems("w.yaml", problems), "w.yaml: goal 'buried': lies inside obstacle 'pillar'");
}

}  // namespace
}  // namespace ifar::sim
