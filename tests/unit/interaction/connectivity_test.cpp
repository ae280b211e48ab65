#include "planner/interaction/connectivity.hpp"

#include <gtest/gtest.h>

#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;
using test::rectangle;

void expectPoint(const Point& actual, double x, double y)
{
  EXPECT_NEAR(actual.x(), x, 1e-9);
  EXPECT_NEAR(actual.y(), y, 1e-9);
}

TEST(ConnectivityTest, DoorwayGivesTwoWaypointsByEquationOne)
{
  const ConnectivityResult result = analyzeConnectivity(test::doorwayScene(), 0, ConnectivitySettings{});
  EXPECT_EQ(result.status, PlanStatus::Found);
  ASSERT_TRUE(result.splits);
  ASSERT_EQ(result.waypoints.size(), 2U);
  // p' on the free faces x = +-0.6, offset min(0.5, d_obs / 2) = 0.5 along the normal.
  expectPoint(result.waypoints[0].boundary_point, 0.6, 0.0);
  expectPoint(result.waypoints[0].position, 1.1, 0.0);
  expectPoint(result.waypoints[0].normal, 1.0, 0.0);
  expectPoint(result.waypoints[1].position, -1.1, 0.0);
  EXPECT_EQ(result.waypoints[0].component, 0U);
  EXPECT_EQ(result.waypoints[1].component, 1U);
  ASSERT_EQ(result.pairs.size(), 2U);
  EXPECT_EQ(result.pairs[0].from, 0U);
  EXPECT_EQ(result.pairs[0].to, 1U);
  EXPECT_EQ(result.pairs[1].from, 1U);
  EXPECT_EQ(result.pairs[1].to, 0U);
}

TEST(ConnectivityTest, TJunctionGivesThreeWaypointsAndSixPairs)
{
  const ConnectivityResult result = analyzeConnectivity(test::tJunctionScene(), 0, ConnectivitySettings{});
  ASSERT_TRUE(result.splits);
  ASSERT_EQ(result.waypoints.size(), 3U);
  EXPECT_EQ(result.pairs.size(), 6U);
  // Stem below, right arm, left arm (order of the free stretches along the counter-clockwise boundary).
  expectPoint(result.waypoints[0].position, 0.0, -0.4);
  expectPoint(result.waypoints[1].position, 1.45, 1.0);
  expectPoint(result.waypoints[2].position, -1.45, 1.0);
}

TEST(ConnectivityTest, NearObstacleHalvesTheOffset)
{
  LocalScene scene = test::doorwayScene();
  scene.background.push_back(rectangle(1.2, -3.0, 2.0, 3.0));  // 0.6 m beyond the right face
  const ConnectivityResult result = analyzeConnectivity(scene, 0, ConnectivitySettings{});
  ASSERT_EQ(result.waypoints.size(), 2U);
  expectPoint(result.waypoints[0].position, 0.9, 0.0);
}

TEST(ConnectivityTest, FreeStandingObjectHasNoWaypoints)
{
  LocalScene scene = test::doorwayScene();
  scene.movable = {rectangle(3.0, -0.5, 4.0, 0.5)};
  const ConnectivityResult result = analyzeConnectivity(scene, 0, ConnectivitySettings{});
  EXPECT_EQ(result.status, PlanStatus::Found);
  EXPECT_FALSE(result.splits);
  EXPECT_TRUE(result.waypoints.empty());
  EXPECT_TRUE(result.pairs.empty());
}

TEST(ConnectivityTest, ObjectTouchingOneWallDoesNotSplit)
{
  LocalScene scene;
  scene.background = {rectangle(-5.0, -1.0, 5.0, 0.0)};
  scene.movable = {rectangle(-0.5, -0.2, 0.5, 0.8)};
  const ConnectivityResult result = analyzeConnectivity(scene, 0, ConnectivitySettings{});
  EXPECT_FALSE(result.splits);
  EXPECT_TRUE(result.waypoints.empty());
}

TEST(ConnectivityTest, TwoTouchingBoxesInAWideDoorEachSplitIt)
{
  LocalScene scene;
  scene.background = {rectangle(-0.5, 1.0, 0.5, 5.0), rectangle(-0.5, -5.0, 0.5, -1.0)};
  scene.movable = {rectangle(-0.6, -0.1, 0.6, 1.2), rectangle(-0.6, -1.2, 0.6, 0.1)};
  for (std::size_t index = 0; index < 2; ++index) {
    const ConnectivityResult result = analyzeConnectivity(scene, index, ConnectivitySettings{});
    ASSERT_TRUE(result.splits) << "box " << index;
    EXPECT_EQ(result.waypoints.size(), 2U) << "box " << index;
    EXPECT_EQ(result.pairs.size(), 2U) << "box " << index;
    // The chord runs from the wall to the neighbour box, so the normal tilts a little: Eq. 1 as is.
    for (const TopologicalWaypoint& waypoint : result.waypoints) {
      EXPECT_GT(std::abs(waypoint.position.x()), 1.0);
      EXPECT_LT(std::abs(waypoint.position.x()), 1.15);
    }
    EXPECT_LT(result.waypoints[0].position.x() * result.waypoints[1].position.x(), 0.0);
  }
}

TEST(ConnectivityTest, DegenerateAndOversizedPolygonsAreRejected)
{
  LocalScene scene = test::doorwayScene();
  const ConnectivitySettings settings;
  scene.movable = {{Point(0.0, 0.0), Point(1.0, 0.0)}};
  EXPECT_EQ(analyzeConnectivity(scene, 0, settings).status, PlanStatus::DegeneratePolygon);
  scene.movable = {rectangle(-0.5, -1.0, -0.5 + 1e-4, 1.0)};  // sliver
  EXPECT_EQ(analyzeConnectivity(scene, 0, settings).status, PlanStatus::DegeneratePolygon);
  // Self-touching: two squares meeting at one vertex, traced as one loop.
  scene.movable = {{Point(0, 0), Point(1, 0), Point(1, 1), Point(2, 1), Point(2, 2), Point(1, 2), Point(1, 1),
                    Point(0, 1)}};
  EXPECT_EQ(analyzeConnectivity(scene, 0, settings).status, PlanStatus::DegeneratePolygon);
  scene.movable = {rectangle(-40.0, -40.0, 40.0, 40.0)};
  EXPECT_EQ(analyzeConnectivity(scene, 0, settings).status, PlanStatus::ObjectTooLarge);
  EXPECT_EQ(analyzeConnectivity(scene, 3, settings).status, PlanStatus::DegeneratePolygon);
  EXPECT_FALSE(analyzeConnectivity(scene, 3, settings).splits);
}

TEST(ConnectivityTest, DegenerateNeighboursAreCountedAndSkipped)
{
  LocalScene scene = test::doorwayScene();
  scene.background.push_back({Point(3.0, 3.0), Point(4.0, 4.0)});
  const ConnectivityResult result = analyzeConnectivity(scene, 0, ConnectivitySettings{});
  EXPECT_EQ(result.skipped_polygons, 1U);
  EXPECT_EQ(result.waypoints.size(), 2U);
}

}  // namespace
}  // namespace ifar::interaction
