// findDoorway: which gaps across the path are doorways, and the straight run chosen through each, on
// hand-made walls sampled like lidar returns (5 cm apart).

#include "executive/doorway/doorway.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace ifar::executive {
namespace {

using geometry::Point;

/// A door `width` wide centred on x = `centre_x` in a 0.2 m wall at y -0.1 .. 0.1 from x -4 to 4, as
/// points 5 cm apart along both faces and across the posts' ends.
std::vector<Point> wallWithDoor(double width, double centre_x = 0.0)
{
  std::vector<Point> points;
  const double half = 0.5 * width;
  for (int step = -80; step <= 80; ++step) {
    const double x = 0.05 * step;
    if (std::abs(x - centre_x) >= half - 1e-9) {
      points.emplace_back(x, -0.1);
      points.emplace_back(x, 0.1);
    }
  }
  for (int step = -2; step <= 2; ++step) {
    points.emplace_back(centre_x - half, 0.05 * step);
    points.emplace_back(centre_x + half, 0.05 * step);
  }
  return points;
}

Footprint vehicle()
{
  Footprint footprint;  // 0.9 m x 0.7 m, reference point at the middle
  return footprint;
}

double angleOf(const Point& direction)
{
  return std::atan2(direction.y(), direction.x());
}

TEST(Doorway, AStraightPathThroughADoorRunsSquareThroughItsMiddle)
{
  const std::vector<Point> walls = wallWithDoor(1.0);
  const std::vector<Point> path{{0.0, -2.5}, {0.0, 2.5}};
  const std::optional<Doorway> door = findDoorway(path, walls, vehicle(), DoorwaySettings{});
  ASSERT_TRUE(door);
  EXPECT_NEAR(door->centre.x(), 0.0, 1e-9);
  EXPECT_LE(std::abs(door->centre.y()), 0.1 + 1e-9);  // between the wall's faces
  EXPECT_NEAR(angleOf(door->heading), M_PI / 2.0, 1e-9);
  EXPECT_NEAR(door->width_m, 1.0, 0.03);
  // 0.15 m either side of the 0.7 m vehicle.
  EXPECT_NEAR(door->clearance_m, 0.15, 1e-9);
  EXPECT_NEAR(door->runStart(DoorwaySettings{}).y(), door->centre.y() - 1.0, 1e-9);
}

TEST(Doorway, APathAcrossADoorAtASlantGetsTheSquareRun)
{
  // The global path bends at the inflated corner of the left post and leaves at 45 degrees, as a
  // visibility-graph path does; the run goes square through the door all the same.
  const std::vector<Point> walls = wallWithDoor(1.0);
  const std::vector<Point> path{{-2.0, -1.5}, {-0.15, -0.2}, {1.5, 1.5}};
  const std::optional<Doorway> door = findDoorway(path, walls, vehicle(), DoorwaySettings{});
  ASSERT_TRUE(door);
  EXPECT_NEAR(door->centre.x(), 0.0, 0.02);
  EXPECT_NEAR(angleOf(door->heading), M_PI / 2.0, 0.03);
  EXPECT_GE(door->clearance_m, 0.13);
}

TEST(Doorway, TheWayBackGoesTheOtherWay)
{
  const std::vector<Point> walls = wallWithDoor(1.0);
  const std::vector<Point> path{{0.2, 2.0}, {0.0, -2.0}};
  const std::optional<Doorway> door = findDoorway(path, walls, vehicle(), DoorwaySettings{});
  ASSERT_TRUE(door);
  EXPECT_NEAR(angleOf(door->heading), -M_PI / 2.0, 0.03);
  EXPECT_LT(door->along(path[0]), -1.5);
}

TEST(Doorway, WideOpeningsAndGapsTooNarrowAreNoDoorways)
{
  const std::vector<Point> path{{0.0, -2.5}, {0.0, 2.5}};
  const std::vector<Point> wide = wallWithDoor(2.0);
  EXPECT_FALSE(findDoorway(path, wide, vehicle(), DoorwaySettings{}));
  // 0.78 m: narrower than the vehicle and the least clearance either side.
  const std::vector<Point> too_narrow = wallWithDoor(0.78);
  EXPECT_FALSE(findDoorway(path, too_narrow, vehicle(), DoorwaySettings{}));
  // 0.82 m: a straight run keeps 0.06 m either side.
  const std::vector<Point> narrow = wallWithDoor(0.82);
  EXPECT_TRUE(findDoorway(path, narrow, vehicle(), DoorwaySettings{}));
}

TEST(Doorway, OnlyDoorsOnTheSearchedStretchAheadCount)
{
  const std::vector<Point> walls = wallWithDoor(1.0);
  // Standing in the door (closer than min_ahead_m), and 4 m before it (beyond look_ahead_m).
  const std::vector<Point> in_door{{0.0, -0.3}, {0.0, 2.5}};
  EXPECT_FALSE(findDoorway(in_door, walls, vehicle(), DoorwaySettings{}));
  const std::vector<Point> far_before{{0.0, -4.0}, {0.0, 2.5}};
  EXPECT_FALSE(findDoorway(far_before, walls, vehicle(), DoorwaySettings{}));
  // Along the wall, past the door, in the corridor below it.
  const std::vector<Point> along_wall{{-3.0, -0.8}, {3.0, -0.8}};
  EXPECT_FALSE(findDoorway(along_wall, walls, vehicle(), DoorwaySettings{}));
  const std::vector<Point> through{{0.0, -2.5}, {0.0, 2.5}};
  ASSERT_TRUE(findDoorway(through, walls, vehicle(), DoorwaySettings{}));
  DoorwaySettings off;
  off.enabled = false;
  EXPECT_FALSE(findDoorway(through, walls, vehicle(), off));
}

TEST(Doorway, NoRunWhenSomethingStandsOnItsLineBeyondTheDoor)
{
  std::vector<Point> walls = wallWithDoor(1.0);
  // A box 0.9 m beyond the door, 0.8 m across its middle: a run square to the door would end in it, and
  // one skewed to pass it would touch a post.
  for (int step = -8; step <= 8; ++step) {
    walls.emplace_back(0.05 * step, 1.0);
  }
  const std::vector<Point> path{{0.0, -2.5}, {0.0, 0.5}, {2.0, 1.5}};
  EXPECT_FALSE(findDoorway(path, walls, vehicle(), DoorwaySettings{}));
}

/// A 2.5 m corridor (walls at y = 0 and 2.5, x -3 .. 5) with a 0.5 m x 1.1 m box across it at x 1 .. 1.5,
/// y 0.7 .. 1.8: a lane 0.7 m wide either side, as a fire-door box pushed into a corridor leaves.
std::vector<Point> corridorWithBox()
{
  std::vector<Point> points;
  for (int step = -60; step <= 100; ++step) {
    points.emplace_back(0.05 * step, 0.0);
    points.emplace_back(0.05 * step, 2.5);
  }
  for (int step = 0; step <= 10; ++step) {
    points.emplace_back(1.0 + 0.05 * step, 0.7);
    points.emplace_back(1.0 + 0.05 * step, 1.8);
  }
  for (int step = 0; step <= 22; ++step) {
    points.emplace_back(1.0, 0.7 + 0.05 * step);
    points.emplace_back(1.5, 0.7 + 0.05 * step);
  }
  return points;
}

TEST(ImpassableGap, ADoorNarrowerThanTheVehicleAndItsClearanceIsImpassable)
{
  const std::vector<Point> path{{0.0, -2.5}, {0.0, 2.5}};
  const std::vector<Point> too_narrow = wallWithDoor(0.78);
  const std::optional<ImpassableGap> gap = findImpassableGap(path, too_narrow, vehicle(), {});
  ASSERT_TRUE(gap);
  EXPECT_NEAR(gap->width_m, 0.78, 0.03);
  EXPECT_NEAR(gap->along_m, 2.4, 0.1);  // the wall's near face
  EXPECT_NEAR(std::abs(gap->first_post.x()), 0.39, 0.03);
  EXPECT_NEAR(gap->second_post.x(), -gap->first_post.x(), 0.03);
  // 0.62 m still is; 0.55 m and a path through a wall (returns 0.05 m apart) are the planner's to see:
  // its inflation by the half width closes them.
  const std::vector<Point> barely = wallWithDoor(0.62);
  EXPECT_TRUE(findImpassableGap(path, barely, vehicle(), {}));
  for (const double width : {0.55, 0.05}) {
    const std::vector<Point> walls = wallWithDoor(width);
    EXPECT_FALSE(findImpassableGap(path, walls, vehicle(), {})) << width;
  }
  // 0.82 m is driven as a doorway; 1.0 m and a wide opening are plain passages.
  for (const double width : {0.82, 1.0, 2.0}) {
    const std::vector<Point> walls = wallWithDoor(width);
    EXPECT_FALSE(findImpassableGap(path, walls, vehicle(), {})) << width;
  }
}

TEST(ImpassableGap, OnlyGapsBetweenTheBumperAndTheLookAheadCount)
{
  const std::vector<Point> walls = wallWithDoor(0.78);
  // 4 m before the door (beyond look_ahead_m), and with the bumper already past the posts.
  const std::vector<Point> far_before{{0.0, -4.0}, {0.0, 2.5}};
  EXPECT_FALSE(findImpassableGap(far_before, walls, vehicle(), {}));
  const std::vector<Point> in_door{{0.0, 0.0}, {0.0, 2.5}};
  EXPECT_FALSE(findImpassableGap(in_door, walls, vehicle(), {}));
}

TEST(ImpassableGap, TheLanesBesideABoxInACorridorAreImpassableTheCorridorBeforeItIsNot)
{
  const std::vector<Point> points = corridorWithBox();
  // Through the north lane, as a graph that inflates by the half width only may route it.
  const std::vector<Point> north{{-1.0, 1.25}, {0.7, 2.15}, {1.8, 2.15}, {4.0, 1.25}};
  const std::optional<ImpassableGap> gap = findImpassableGap(north, points, vehicle(), {});
  ASSERT_TRUE(gap);
  // Found where the lane begins: from the wall to the box's corner, a little wider than the lane.
  EXPECT_GE(gap->width_m, 0.7 - 1e-9);
  EXPECT_LT(gap->width_m, 0.8);
  const Point on_box = gap->first_post.y() < gap->second_post.y() ? gap->first_post : gap->second_post;
  const Point on_wall = gap->first_post.y() < gap->second_post.y() ? gap->second_post : gap->first_post;
  EXPECT_NEAR(on_box.y(), 1.8, 1e-9);
  EXPECT_NEAR(on_box.x(), 1.0, 1e-9);
  EXPECT_NEAR(on_wall.y(), 2.5, 1e-9);
  EXPECT_LE(gap->along_m, 2.2);  // before the path's corner at the lane's west end
  // Up the corridor's middle to 0.8 m before the box, and along it beside the box's far end.
  const std::vector<Point> before{{-2.5, 1.25}, {0.2, 1.25}};
  EXPECT_FALSE(findImpassableGap(before, points, vehicle(), {}));
  const std::vector<Point> past_the_end{{3.0, 0.6}, {3.0, 2.0}};
  EXPECT_FALSE(findImpassableGap(past_the_end, points, vehicle(), {}));
}

}  // namespace
}  // namespace ifar::executive
