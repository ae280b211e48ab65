#include "executive/follower/follower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "executive/follower/obstacle_grid.hpp"
#include "tests/unit/executive/simulation.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;
using geometry::Pose2;

/// Points every 5 cm along the segment from `from` to `to`.
void addWall(std::vector<Point>& points, const Point& from, const Point& to)
{
  const int count = std::max(1, static_cast<int>(std::ceil((to - from).norm() / 0.05)));
  for (int index = 0; index <= count; ++index) {
    points.push_back(from + (to - from) * (static_cast<double>(index) / count));
  }
}

double clearance(const Pose2& pose, const std::vector<Point>& points, const Footprint& footprint)
{
  double nearest = std::numeric_limits<double>::infinity();
  for (const Point& point : points) {
    nearest = std::min(nearest, footprint.distance(pose, point));
  }
  return nearest;
}

class FollowerTest : public ::testing::Test {
 protected:
  common::VehicleSettings vehicle_;
  DifferentialDrive drive_{vehicle_};
  FollowerSettings settings_;
};

TEST_F(FollowerTest, DrivesStraightInFreeSpace)
{
  const FollowerResult result = follow({0.0, 0.0, 0.0}, {5.0, 0.0}, true, {}, settings_, drive_);
  EXPECT_EQ(result.status, FollowerStatus::Moving);
  EXPECT_NEAR(result.command.linear, settings_.max_linear_velocity, 1e-9);
  EXPECT_NEAR(result.command.angular, 0.0, 1e-9);
  EXPECT_EQ(result.free_arcs, result.arcs);
}

TEST_F(FollowerTest, BrakesAtConstantDecelerationTowardATargetToStopAt)
{
  // 0.25 m beyond the tolerance's edge with a 1 m braking distance: half the top speed (a linear ramp
  // over the same distance would give a quarter; over the old 1.5 m, 0.37 of it).
  settings_.slow_down_distance_m = 1.0;
  const double distance = settings_.goal_tolerance_m + 0.25;
  const FollowerResult stopping = follow({0.0, 0.0, 0.0}, {distance, 0.0}, true, {}, settings_, drive_);
  EXPECT_NEAR(stopping.command.linear, 0.5 * settings_.max_linear_velocity, 1e-9);

  // A waypoint passed through keeps the top speed.
  const FollowerResult passing = follow({0.0, 0.0, 0.0}, {distance, 0.0}, false, {}, settings_, drive_);
  EXPECT_NEAR(passing.command.linear, settings_.max_linear_velocity, 1e-9);

  // At the tolerance's edge it still moves, at the quarter-speed floor.
  const FollowerResult creeping =
      follow({0.0, 0.0, 0.0}, {settings_.goal_tolerance_m + 0.01, 0.0}, true, {}, settings_, drive_);
  EXPECT_NEAR(creeping.command.linear, 0.25 * settings_.max_linear_velocity, 1e-9);
}

TEST_F(FollowerTest, TurnsTowardTargetBehind)
{
  const FollowerResult result = follow({0.0, 0.0, 0.0}, {-5.0, 0.5}, true, {}, settings_, drive_);
  EXPECT_EQ(result.status, FollowerStatus::Moving);
  EXPECT_GT(result.command.angular, 0.5);  // target is behind and slightly left: turn left hard
}

/// Drives follow() toward `target` from `start` in 20 ms cycles; the distance driven until it arrives
/// (infinity when it does not within a minute).
double drivenTo(const Pose2& start, const Point& target, const FollowerSettings& settings,
                const DifferentialDrive& drive)
{
  Pose2 pose = start;
  double driven = 0.0;
  for (int cycle = 0; cycle < 3000; ++cycle) {
    const FollowerResult result = follow(pose, target, true, {}, settings, drive);
    if (result.status == FollowerStatus::Arrived) {
      return driven;
    }
    const Pose2 next = testing::drive(pose, result.command, 0.02);
    driven += (next.position() - pose.position()).norm();
    pose = next;
  }
  return std::numeric_limits<double>::infinity();
}

TEST_F(FollowerTest, TurnsOnTheSpotWhereThePathTurnsSharplyInsteadOfLooping)
{
  settings_.turn_in_place_rad = M_PI / 2.0;
  // A target square to the left, or far behind: the vehicle pivots first, then drives nearly straight.
  const FollowerResult square = follow({0.0, 0.0, 0.0}, {0.0, 3.0}, true, {}, settings_, drive_);
  EXPECT_EQ(square.command.linear, 0.0);
  EXPECT_GT(square.command.angular, 0.5);
  const double straight = 3.0 - settings_.goal_tolerance_m;
  EXPECT_LT(drivenTo({0.0, 0.0, 0.0}, {0.0, 3.0}, settings_, drive_), straight + 0.35);
  EXPECT_LT(drivenTo({0.0, 0.0, 0.0}, {-2.1, 2.1}, settings_, drive_), straight + 0.35);
  // 45 degrees off the way on: at most three quarters of top speed ((90 - 45) / (90 - 30)), turning
  // toward it; 20 degrees off: top speed allowed.
  const FollowerResult oblique = follow({0.0, 0.0, 0.0}, {3.0, 3.0}, true, {}, settings_, drive_);
  EXPECT_LE(oblique.command.linear, 0.75 * settings_.max_linear_velocity + 1e-9);
  EXPECT_GT(oblique.command.angular, 0.0);
  const FollowerResult slight =
      follow({0.0, 0.0, 0.0}, {3.0 * std::cos(0.35), 3.0 * std::sin(0.35)}, false, {}, settings_, drive_);
  EXPECT_NEAR(slight.command.linear, settings_.max_linear_velocity, 1e-9);
  // Without the cap, the fastest arcs swing wide: a loop's worth longer.
  FollowerSettings uncapped = settings_;
  uncapped.turn_in_place_rad = 0.0;
  EXPECT_GT(drivenTo({0.0, 0.0, 0.0}, {-2.1, 2.1}, uncapped, drive_), straight + 0.75);
}

TEST_F(FollowerTest, ReversesTowardATargetBehindInAnAisleTooNarrowToTurnIn)
{
  // A 1.24 m aisle along x, closed 0.8 m ahead; the target 3 m behind. Turning on the spot is not free
  // (the footprint's circumradius is 0.57 m), so no forward arc gets closer; reversing does, straight
  // down the aisle at the reverse speed.
  std::vector<Point> walls;
  addWall(walls, {-3.0, 0.62}, {1.0, 0.62});
  addWall(walls, {-3.0, -0.62}, {1.0, -0.62});
  addWall(walls, {1.0, -0.62}, {1.0, 0.62});
  const Pose2 pose{0.2, 0.0, 0.0};
  const Point target(-3.0, 0.0);
  const FollowerResult forward = follow(pose, target, false, walls, settings_, drive_);
  EXPECT_LE(forward.progress_m, 0.01) << forward.reason;
  const double reverse_speed = 0.2;
  const FollowerResult reversing =
      followReversing(pose, target, walls, settings_, 0.05, reverse_speed, drive_);
  ASSERT_EQ(reversing.status, FollowerStatus::Moving) << reversing.reason;
  EXPECT_NEAR(reversing.command.linear, -reverse_speed, 1e-9);
  EXPECT_NEAR(reversing.command.angular, 0.0, 1e-9);
  // Cost-to-go near walls costs more than its length (navigation_proximity_weight): at least the arc's.
  EXPECT_GE(reversing.progress_m, reverse_speed * settings_.horizon_s - 1e-9);
  EXPECT_EQ(reversing.reason.rfind("reversing: ", 0), 0U) << reversing.reason;
}

TEST_F(FollowerTest, ReportsArrivalWithinTolerance)
{
  const FollowerResult result = follow({0.0, 0.0, 0.0}, {0.2, 0.0}, true, {}, settings_, drive_);
  EXPECT_EQ(result.status, FollowerStatus::Arrived);
  EXPECT_TRUE(result.command.isZero());
}

TEST_F(FollowerTest, AvoidsBoxAcrossTheStraightLine)
{
  // A 0.6 m x 2 m box across the line from (0, 0) to (6, 0).
  std::vector<Point> box;
  addWall(box, {2.7, -1.0}, {2.7, 1.0});
  addWall(box, {3.3, -1.0}, {3.3, 1.0});
  addWall(box, {2.7, -1.0}, {3.3, -1.0});
  addWall(box, {2.7, 1.0}, {3.3, 1.0});
  const Point target(6.0, 0.0);

  Pose2 pose{0.0, 0.0, 0.0};
  double closest = std::numeric_limits<double>::infinity();
  bool arrived = false;
  for (int step = 0; step < 1000 && !arrived; ++step) {
    const FollowerResult result = follow(pose, target, true, box, settings_, drive_);
    ASSERT_NE(result.status, FollowerStatus::Blocked) << "at step " << step;
    arrived = result.status == FollowerStatus::Arrived;
    pose = testing::drive(pose, result.command, 0.05);
    closest = std::min(closest, clearance(pose, box, settings_.footprint));
  }
  EXPECT_TRUE(arrived);
  EXPECT_LE((pose.position() - target).norm(), settings_.goal_tolerance_m + 1e-6);
  EXPECT_GT(closest, 0.1);  // kept (nearly) the 0.15 m clearance all the way round
}

TEST_F(FollowerTest, StopsWhenBoxedIn)
{
  // Walls 0.2 m from every side of the 0.9 m x 0.7 m footprint: no arc, not even turning on the spot, is
  // free.
  std::vector<Point> walls;
  addWall(walls, {-0.65, -0.55}, {0.65, -0.55});
  addWall(walls, {-0.65, 0.55}, {0.65, 0.55});
  addWall(walls, {-0.65, -0.55}, {-0.65, 0.55});
  addWall(walls, {0.65, -0.55}, {0.65, 0.55});
  const FollowerResult result = follow({0.0, 0.0, 0.0}, {5.0, 0.0}, true, walls, settings_, drive_);
  EXPECT_EQ(result.status, FollowerStatus::Blocked);
  EXPECT_TRUE(result.command.isZero());
  EXPECT_EQ(result.free_arcs, 0);
  EXPECT_NE(result.reason.find("blocked"), std::string::npos);
}

TEST_F(FollowerTest, CanLeaveWhenAlreadyCloserThanClearance)
{
  // A wall 5 cm behind the rear: closer than the 0.15 m clearance, but driving away is fine.
  std::vector<Point> wall;
  addWall(wall, {-0.5, -2.0}, {-0.5, 2.0});
  const FollowerResult result = follow({0.0, 0.0, 0.0}, {5.0, 0.0}, true, wall, settings_, drive_);
  EXPECT_EQ(result.status, FollowerStatus::Moving);
  EXPECT_GT(result.command.linear, 0.0);
}

TEST_F(FollowerTest, RejectsNonFinitePose)
{
  const FollowerResult result =
      follow({std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}, {5.0, 0.0}, true, {}, settings_, drive_);
  EXPECT_EQ(result.status, FollowerStatus::InvalidInput);
  EXPECT_TRUE(result.command.isZero());
}

TEST(ObstacleGrid, FindsNearPointsAndSkipsBadOnes)
{
  const std::vector<Point> points{
      {1.0, 1.0}, {1.2, 1.1}, {-3.0, 0.0}, {50.0, 50.0}, {std::numeric_limits<double>::quiet_NaN(), 0.0}};
  const ObstacleGrid grid(points, {0.0, 0.0}, 5.0, 0.25);
  EXPECT_EQ(grid.size(), 3u);  // the far point is out of range, the NaN skipped
  EXPECT_EQ(grid.skippedPoints(), 1u);
  std::vector<Point> near;
  grid.forEachNear({1.1, 1.0}, 0.3, [&near](const Point& point) { near.push_back(point); });
  ASSERT_EQ(near.size(), 2u);
  int far_hits = 0;
  grid.forEachNear({-3.0, 0.0}, 0.1, [&far_hits](const Point&) { ++far_hits; });
  EXPECT_EQ(far_hits, 1);
}

}  // namespace
}  // namespace ifar::executive
