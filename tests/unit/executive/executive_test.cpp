#include "executive/modes/executive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "executive/follower/arc.hpp"
#include "tests/unit/executive/simulation.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;
using geometry::Pose2;

constexpr std::int64_t kCycleUs = 20'000;  // 50 Hz

Waypoint waypoint(double x, double y, WaypointKind kind = WaypointKind::Free, std::int64_t object_id = -1,
                  int plan_index = -1)
{
  Waypoint result;
  result.position = Point(x, y);
  result.kind = kind;
  result.object_id = object_id;
  result.push_plan_index = plan_index;
  return result;
}

Path straightPath(std::int64_t sequence = 1, std::int64_t planned_us = 0)
{
  Path path;
  path.utime = planned_us;
  path.goal_id = 5;
  path.sequence = sequence;
  path.valid = true;
  path.waypoints = {waypoint(0.0, 0.0), waypoint(3.0, 0.0)};
  return path;
}

/// start -> topological waypoint (1, 0) -> push waypoint (3, 0) -> goal (5, 0); object 9 is pushed along
/// +x from the contact pose (1.5, 0) for 3 s at 0.3 m/s.
Path pushPath(std::int64_t sequence = 1, std::int64_t planned_us = 0)
{
  Path path = straightPath(sequence, planned_us);
  PushPlan plan;
  plan.object_id = 9;
  plan.contact_pose = {1.5, 0.0, 0.0};
  PushControl control;
  control.linear_velocity = 0.3;
  control.duration_s = 3.0;
  control.expected_vehicle_pose = {2.4, 0.0, 0.0};
  plan.controls.push_back(control);
  plan.expected_force_n = 100.0;
  plan.push_distance_m = 0.9;
  plan.travel_m = 1.5;
  plan.expected_cost = 2.4;
  plan.affordance = 0.3;
  path.push_plans.push_back(plan);
  path.waypoints = {waypoint(0.0, 0.0), waypoint(1.0, 0.0, WaypointKind::Topological, 9, 0),
                    waypoint(3.0, 0.0, WaypointKind::Push, 9, 0), waypoint(5.0, 0.0)};
  return path;
}

/// How a drive through the office's 1.0 m door went (ExecutiveTest::driveThroughDoor).
struct DoorDrive {
  double seconds_through = 0.0;  ///< until the vehicle is 1 m beyond the wall; 0 when it never is
  int stalls = 0;
  int doorway_cycles = 0;          ///< cycles in a doorway run
  double least_clearance_m = 1e9;  ///< of the footprint to a wall point
  std::string last_reason;
};

class ExecutiveTest : public ::testing::Test {
 protected:
  ExecutiveTest() : executive_(settings_, vehicle_) {}

  /// Every input fresh at `now_us`, the vehicle at `pose_`, no obstacles.
  Inputs freshInputs(std::int64_t now_us, const Path& path, double force_n = 0.0) const
  {
    Inputs inputs;
    inputs.pose = Stamped<Pose2>{pose_, now_us};
    inputs.path = Stamped<Path>{path, now_us};
    inputs.force = Stamped<ForceReading>{ForceReading{force_n, false}, now_us};
    inputs.motor = Stamped<MotorReading>{MotorReading{true, false, ""}, now_us};
    inputs.obstacles = Stamped<std::vector<Point>>{{}, now_us};
    return inputs;
  }

  /// Runs `cycles` control cycles with fresh inputs, moving the vehicle by the command (unless stalled).
  Output run(int cycles, const Path& path, double force_n = 0.0, bool stalled = false)
  {
    Output output;
    for (int cycle = 0; cycle < cycles; ++cycle) {
      now_us_ += kCycleUs;
      output = executive_.step(now_us_, freshInputs(now_us_, path, force_n));
      modes_.push_back(output.status.mode);
      if (output.affordance) {
        events_.push_back(*output.affordance);
      }
      if (!stalled) {
        pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
      }
    }
    return output;
  }

  bool visited(Mode mode) const { return std::find(modes_.begin(), modes_.end(), mode) != modes_.end(); }

  /// Drives `executive` from 1.5 m below a 0.72 m gap (wide enough for the planner's inflated map, too
  /// narrow for the 0.7 m vehicle plus its clearance) toward a waypoint 1.5 m beyond it, until
  /// `stop_after` stalls or a blocked-passage report; returns the report (if any) and counts the stalls.
  std::optional<BlockedPassage> driveAtNarrowGap(Executive& executive, int stop_after, int& stalls,
                                                 double goal_y = 1.5);

  /// Drives `executive` from `start` in the corridor below the office's 1.0 m door (doorWalls()) toward a
  /// room beyond it along a visibility-graph path (bent at the left post's inflated corner, crossing the
  /// door at a slant).
  DoorDrive driveThroughDoor(Executive& executive, const Pose2& start);

  ExecutiveSettings settings_;
  common::VehicleSettings vehicle_;
  Executive executive_;
  Pose2 pose_{0.0, 0.0, 0.0};
  std::int64_t now_us_ = 1'000'000'000;
  std::vector<Mode> modes_;
  std::vector<AffordanceEvent> events_;
};

TEST_F(ExecutiveTest, NoProgressTowardTheGoalEscalatesByDroppingTheRouteAhead)
{
  // Held in place while following (a livelock of stalls and escapes that get nowhere; the stall series
  // is not reported here): after progress.timeout_s of no progress the executive drops the route ahead
  // as a blocked passage, says so, and counts it.
  settings_.progress.timeout_s = 10.0;
  settings_.blocked_passage_stalls = 0;
  executive_ = Executive(settings_, vehicle_);
  const Path path = straightPath();
  std::optional<Output> escalated;
  int cycles = 0;
  while (cycles < 1500 && !escalated) {
    const Output output = run(1, path, 0.0, true);
    ++cycles;
    if (output.escalation) {
      escalated = output;
    }
  }
  ASSERT_TRUE(escalated.has_value());
  EXPECT_NEAR(cycles * kCycleUs * 1e-6, 10.0, 0.1);
  EXPECT_NE(escalated->escalation->find("escalation 1: no progress toward the goal for 10 s"),
            std::string::npos)
      << *escalated->escalation;
  ASSERT_TRUE(escalated->blocked_passage.has_value());
  EXPECT_NE(escalated->blocked_passage->text.find("no progress toward the goal"), std::string::npos);
  EXPECT_EQ(escalated->blocked_passage->from, Point(0.0, 0.0));
  EXPECT_EQ(escalated->status.escalations, 1);
  // The next one only after another timeout.
  const Output later = run(250, path, 0.0, true);
  EXPECT_EQ(later.status.escalations, 1);
  EXPECT_EQ(run(300, path, 0.0, true).status.escalations, 2);
}

TEST_F(ExecutiveTest, NoEscalationWhileTheVehicleGetsCloser)
{
  settings_.progress.timeout_s = 2.0;
  executive_ = Executive(settings_, vehicle_);
  Path path = straightPath();
  path.waypoints.back().position = Point(12.0, 0.0);
  for (int cycle = 0; cycle < 1000 && executive_.mode() != Mode::Arrived; ++cycle) {
    const Output output = run(1, path);
    ASSERT_FALSE(output.escalation.has_value()) << *output.escalation;
  }
  EXPECT_EQ(executive_.mode(), Mode::Arrived);
}

TEST_F(ExecutiveTest, IdleWithoutPath)
{
  Inputs inputs = freshInputs(now_us_, straightPath());
  inputs.path.reset();
  const Output output = executive_.step(now_us_, inputs);
  EXPECT_EQ(output.status.mode, Mode::Idle);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_EQ(output.status.stale, kStalePath);
  EXPECT_EQ(output.status.waypoint_index, -1);
}

TEST_F(ExecutiveTest, FollowsPathThenArrives)
{
  const Output first = run(1, straightPath());
  EXPECT_EQ(first.status.mode, Mode::Follow);
  EXPECT_TRUE(first.mode_changed);
  EXPECT_EQ(first.status.goal_id, 5);
  const Output moving = run(25, straightPath());
  EXPECT_GT(moving.command.linear, 0.3);
  EXPECT_LE(moving.command.linear, vehicle_.max_linear_velocity);
  const Output last = run(500, straightPath());
  EXPECT_EQ(last.status.mode, Mode::Arrived);
  EXPECT_TRUE(last.command.isZero());
  EXPECT_NEAR(pose_.x, 3.0, settings_.goal_tolerance_m);
}

TEST_F(ExecutiveTest, ANewPlanAfterArrivalDoesNotRestartForCentimetres)
{
  const Output arrived = run(500, straightPath());
  ASSERT_EQ(arrived.status.mode, Mode::Arrived);
  // Coasted to just past the goal tolerance: the planner's next plan leaves it arrived.
  pose_ = Pose2{3.0 - settings_.goal_tolerance_m - 0.05, 0.0, 0.0};
  EXPECT_EQ(run(1, straightPath(2, 1)).status.mode, Mode::Arrived);
  // Moved away for real: a new plan is followed again.
  pose_ = Pose2{3.0 - settings_.goal_tolerance_m - 0.3, 0.0, 0.0};
  EXPECT_EQ(run(1, straightPath(3, 2)).status.mode, Mode::Follow);
}

TEST_F(ExecutiveTest, StoppingBetweenTheWaypointAndGoalTolerancesIsNotArrival)
{
  // Closer to the goal than an intermediate waypoint needs, farther than arrival needs: drive on.
  ASSERT_GT(settings_.waypoint_tolerance_m, settings_.goal_tolerance_m);
  settings_.follower.goal_tolerance_m = settings_.waypoint_tolerance_m;  // as loadExecutiveSettings sets it
  Executive executive(settings_, vehicle_);
  pose_ = Pose2{3.0 - 0.5 * (settings_.waypoint_tolerance_m + settings_.goal_tolerance_m), 0.0, 0.0};
  Output output;
  for (int cycle = 0; cycle < 500 && output.status.mode != Mode::Arrived; ++cycle) {
    now_us_ += kCycleUs;
    output = executive.step(now_us_, freshInputs(now_us_, straightPath()));
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
  }
  EXPECT_EQ(output.status.mode, Mode::Arrived) << output.status.reason;
  EXPECT_LE(std::abs(pose_.x - 3.0), settings_.goal_tolerance_m);
}

TEST_F(ExecutiveTest, AWaypointTheVehicleIsBeyondCountsAsPassedWithinThePassRadius)
{
  // The corner waypoint (2.0, 0.6) stands where a door post's inflated corner would: the vehicle goes by
  // 0.67 m from it, outside waypoint_tolerance_m. Beyond it (on the next leg's side of the line through
  // it square to that leg) and within waypoint_pass_radius_m it is passed; short of it, or farther than
  // the pass radius, it is still the target.
  ASSERT_LT(settings_.waypoint_tolerance_m, 0.67);
  ASSERT_GT(settings_.waypoint_pass_radius_m, 0.67);
  ASSERT_LT(settings_.waypoint_pass_radius_m, 1.5);
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, 0.0), waypoint(2.0, 0.6), waypoint(6.0, 0.0)};
  const auto target_from = [&](const Pose2& pose) {
    Executive executive(settings_, vehicle_);
    pose_ = pose;
    now_us_ += kCycleUs;
    return executive.step(now_us_, freshInputs(now_us_, path)).status.target;
  };
  EXPECT_NEAR(target_from(Pose2{2.3, 0.0, 0.0}).x(), 6.0, 1e-9);  // beyond, 0.67 m away
  EXPECT_NEAR(target_from(Pose2{1.7, 0.0, 0.0}).x(), 2.0, 1e-9);  // short of it, 0.67 m away
  EXPECT_NEAR(target_from(Pose2{3.4, 0.0, 0.0}).x(), 2.0, 1e-9);  // beyond, but 1.52 m away
}

TEST_F(ExecutiveTest, AfterAStallAtACornerTheNextWaypointIsFollowedRoundIt)
{
  // Tunnel-1 t2 at 565 s (the obstacle points the executive had), the rock's corner moved to the origin:
  // rock at x <= 0, y <= 0, the pushed crate's face 0.6 m below at y = -0.6. The path's corner vertex
  // (0.32, 0.27) is the disc-inflated corner a layer cell off: reaching it, the vehicle faces the rock
  // with its bumper a few centimetres from the face, and no forward arc toward the next waypoint keeps
  // the guard's clearance. Aiming at the vertex after each stall, it stalled there 75 times; after a
  // second stall there the vertex, within the pass radius, counts as passed, and the follower's cost-to-go
  // to the next waypoint leads round the corner.
  std::vector<Point> walls;
  for (double x = -8.0; x <= 0.0; x += 0.05) {
    walls.emplace_back(x, 0.0);
  }
  for (double y = -1.0; y < 0.0; y += 0.05) {
    walls.emplace_back(0.0, y);
  }
  for (double x = 0.2; x <= 3.6; x += 0.05) {
    walls.emplace_back(x, -0.6);
  }
  Path path = straightPath();
  path.waypoints = {waypoint(0.70, -0.02), waypoint(0.32, 0.27), waypoint(-24.0, 0.27)};
  pose_ = Pose2{0.70, -0.02, 169.7 * M_PI / 180.0};
  int stalls = 0;
  bool stalling = false;
  std::string last_reason;
  for (int cycle = 0; cycle < 3000 && pose_.x > -2.0; ++cycle) {
    now_us_ += kCycleUs;
    if (cycle % 5 == 0 && pose_.x > 0.0) {
      // The planner's path at 10 Hz, from where the vehicle is: round the corner vertex while it is east
      // of the rock.
      ++path.sequence;
      path.utime = now_us_;
      path.waypoints.front() = waypoint(pose_.x, pose_.y);
    }
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive_.step(now_us_, inputs);
    last_reason = output.status.reason;
    const bool stalled = output.status.reason.find("stalled for") != std::string::npos;
    stalls += stalled && !stalling ? 1 : 0;
    stalling = stalled;
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
  }
  EXPECT_LT(pose_.x, -2.0) << "ended at (" << pose_.x << ", " << pose_.y << ", " << pose_.heading
                           << ") after " << stalls << " stalls: " << last_reason;
  EXPECT_LE(stalls, 2);
}

TEST_F(ExecutiveTest, FollowingThatGetsNowhereBacksOffAndTriesAgain)
{
  // Facing +y with a wall 5 cm off the right side and the goal 2.3 m behind: turning round would sweep
  // the wall and every forward arc leads away, so the follower only dithers. After stall_timeout_s the
  // executive backs up pusher.release_m and follows again.
  std::vector<Point> wall;
  for (double y = -4.0; y <= 4.0; y += 0.05) {
    wall.emplace_back(0.40, y);
  }
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, 0.0), waypoint(0.0, -2.3)};
  pose_ = Pose2{0.0, 0.0, 0.5 * M_PI};
  bool backed_up = false;
  double first_backoff_s = -1.0;
  std::string last_reason;
  double stalled_y = 0.0;  // where the first back-off began
  double lowest_y = 0.0;
  for (int cycle = 0; cycle < 1500; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{wall, now_us_};
    const Output output = executive_.step(now_us_, inputs);
    last_reason = std::to_string(static_cast<int>(output.status.mode)) + " " + output.status.reason;
    if (output.status.reason.find("stalled for") != std::string::npos) {
      backed_up = true;
      ASSERT_LT(output.command.linear, 1e-9) << output.status.reason;
      if (first_backoff_s < 0.0) {
        first_backoff_s = cycle * kCycleUs * 1e-6;
        stalled_y = pose_.y;
      }
    }
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
    lowest_y = std::min(lowest_y, pose_.y);
  }
  ASSERT_TRUE(backed_up) << "ended at (" << pose_.x << ", " << pose_.y << ", " << pose_.heading
                         << "): " << last_reason;
  EXPECT_GE(first_backoff_s, settings_.stall_timeout_s);
  EXPECT_LT(lowest_y, stalled_y - settings_.pusher.release_m + 0.05);  // backed up the whole distance
}

TEST_F(ExecutiveTest, BackingUpAlongAWallAtASlantIsNotStoppedByRounding)
{
  // As above, turned 0.3 rad off the axes: backing straight up brings the wall behind the rear corner to
  // the side's 5 cm, the guard's clearance, which computed at the slant comes out a rounding below it
  // (office2x-3+4 t4 stood wedged so in a door for 230 s).
  const double heading = 0.5 * M_PI + 0.3;
  const Point forward(std::cos(heading), std::sin(heading));
  const Point right(forward.y(), -forward.x());
  std::vector<Point> wall;
  for (double along = -4.0; along <= 4.0; along += 0.05) {
    wall.push_back(forward * along + right * (0.35 + 0.05));
  }
  Path path = straightPath();
  const Point behind = -2.3 * forward;
  path.waypoints = {waypoint(0.0, 0.0), waypoint(behind.x(), behind.y())};
  pose_ = Pose2{0.0, 0.0, heading};
  double stalled_along = 1.0;  // where the first back-off began, along the heading
  double least_along = 0.0;
  std::string last_reason;
  for (int cycle = 0; cycle < 1500; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{wall, now_us_};
    const Output output = executive_.step(now_us_, inputs);
    last_reason = output.status.reason;
    const double along = pose_.position().dot(forward);
    if (output.status.reason.find("stalled for") != std::string::npos && stalled_along > 0.5) {
      stalled_along = along;
    }
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
    least_along = std::min(least_along, pose_.position().dot(forward));
  }
  ASSERT_LT(stalled_along, 0.5) << "never stalled: " << last_reason;
  EXPECT_LT(least_along, stalled_along - settings_.pusher.release_m + 0.05) << last_reason;
}

/// A door `width` wide (centred on x = 0) in a 0.2 m wall at y 0 .. 0.2, as obstacle points 5 cm apart.
std::vector<Point> doorWalls(double width = 1.0)
{
  std::vector<Point> walls;
  const double half = 0.5 * width;
  for (double x = -4.0; x <= 4.0; x += 0.05) {
    if (std::abs(x) >= half) {
      walls.emplace_back(x, 0.0);
      walls.emplace_back(x, 0.2);
    }
  }
  for (double y = 0.0; y <= 0.2; y += 0.05) {
    walls.emplace_back(-half, y);
    walls.emplace_back(half, y);
  }
  return walls;
}

TEST_F(ExecutiveTest, StalledWithTheBackAgainstADoorPostDrivesAheadInstead)
{
  // Turned away from a 1.0 m door (x -0.5 .. 0.5 in a 0.2 m wall at y 0 .. 0.2) with the rear corner
  // against its left post, the goal through the door: turning toward it swings the rear into the
  // post, backing up would close in on the post too. After stall_timeout_s the executive drives ahead
  // pusher.release_m (where there is room) and follows again from there.
  const std::vector<Point> walls = doorWalls();
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, -0.35), waypoint(0.25, 1.5)};
  pose_ = Pose2{-0.03, -0.35, -28.0 * M_PI / 180.0};
  bool drove_ahead = false;
  bool backed_up = false;
  std::string last_reason;
  for (int cycle = 0; cycle < 1500 && !drove_ahead; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive_.step(now_us_, inputs);
    last_reason = output.status.reason;
    drove_ahead = output.status.reason.find("driving ahead") != std::string::npos;
    backed_up = backed_up || output.status.reason.find("backing up") != std::string::npos;
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
  }
  EXPECT_TRUE(drove_ahead) << "ended at (" << pose_.x << ", " << pose_.y << ", " << pose_.heading
                           << "): " << last_reason;
  EXPECT_FALSE(backed_up);
}

TEST_F(ExecutiveTest, StallEscapeHeldInPlaceTriesTheOtherWayThenFollowsAgain)
{
  // As above, but something the guard does not see holds the vehicle while it drives ahead (a box edge
  // below the scan, wheels slipping): the escape may not drive ahead for good. After
  // stall_recovery.standstill_timeout_s standing still it backs up instead, and follows again when
  // that is held too.
  const std::vector<Point> walls = doorWalls();
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, -0.35), waypoint(0.25, 1.5)};
  pose_ = Pose2{-0.03, -0.35, -28.0 * M_PI / 180.0};
  std::optional<std::int64_t> ahead_since_us;
  std::int64_t longest_ahead_us = 0;
  bool tried_back = false;
  std::string last_reason;
  for (int cycle = 0; cycle < 1500; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive_.step(now_us_, inputs);
    last_reason = output.status.reason;
    const bool ahead = output.status.reason.find("driving ahead") != std::string::npos;
    if (ahead) {
      ahead_since_us = ahead_since_us.value_or(now_us_);
      longest_ahead_us = std::max(longest_ahead_us, now_us_ - *ahead_since_us);
      continue;  // held: the pose does not move
    }
    ahead_since_us.reset();
    tried_back = tried_back || output.status.reason.find("backing up") != std::string::npos;
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
  }
  ASSERT_GT(longest_ahead_us, 0) << "never drove ahead: " << last_reason;
  EXPECT_LE(static_cast<double>(longest_ahead_us) * 1e-6, settings_.stall_recovery.standstill_timeout_s + 0.5)
      << last_reason;
  EXPECT_TRUE(tried_back) << last_reason;
}

TEST_F(ExecutiveTest, WedgedFacingIntoADeadEndAisleReversesOutTowardAWaypointBehind)
{
  // Facing at a slant into a 1.24 m aisle closed 0.8 m ahead (too narrow to turn on the spot), the goal
  // behind, out where the aisle opens at x -2: forward arcs only drive deeper, and straight back closes
  // in on the wall at the slant (Willow t7 was wedged so for 150 s). The stall escape reverses along the
  // cost-to-go, turns where the aisle opens and arrives.
  std::vector<Point> walls;
  for (double x = -2.0; x <= 1.0; x += 0.05) {
    walls.emplace_back(x, 0.62);
    walls.emplace_back(x, -0.62);
  }
  for (double y = -0.62; y <= 0.62; y += 0.05) {
    walls.emplace_back(1.0, y);
  }
  Path path = straightPath();
  path.waypoints = {waypoint(0.2, 0.0), waypoint(-3.5, -1.0)};
  pose_ = Pose2{0.2, 0.05, -17.0 * M_PI / 180.0};
  bool reversed = false;
  Output output;
  for (int cycle = 0; cycle < 60 * 50 && output.status.mode != Mode::Arrived; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    output = executive_.step(now_us_, inputs);
    if (output.status.reason.find("the way on is behind") != std::string::npos) {
      reversed = true;
      ASSERT_LT(output.command.linear, 0.0) << output.status.reason;
    }
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
    for (const Point& wall : walls) {
      ASSERT_GT(settings_.follower.footprint.distance(pose_, wall), 0.0) << "hit the aisle wall";
    }
  }
  EXPECT_TRUE(reversed);
  EXPECT_EQ(output.status.mode, Mode::Arrived)
      << "ended at (" << pose_.x << ", " << pose_.y << ", " << pose_.heading << "): " << output.status.reason;
}

std::optional<BlockedPassage> ExecutiveTest::driveAtNarrowGap(Executive& executive, int stop_after,
                                                              int& stalls, double goal_y)
{
  const std::vector<Point> walls = doorWalls(0.72);
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, -1.5), waypoint(0.0, goal_y)};
  pose_ = Pose2{0.0, -1.5, 0.5 * M_PI};
  std::optional<BlockedPassage> reported;
  stalls = 0;
  bool was_stalled = false;
  for (int cycle = 0; cycle < 3000 && !reported && stalls < stop_after; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive.step(now_us_, inputs);
    const bool stalled = output.status.reason.find("stalled for") != std::string::npos;
    stalls += stalled && !was_stalled ? 1 : 0;
    was_stalled = stalled;
    reported = output.blocked_passage;
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
  }
  return reported;
}

TEST_F(ExecutiveTest, AGapTooNarrowAheadIsReportedOnSightOncePerRepeatInterval)
{
  // A 0.72 m gap 1.5 m ahead: narrower than the vehicle and 5 cm either side. Reported on the first
  // cycle, before the vehicle gets there, toward the path point 1 m beyond the gap (everywhere: no
  // object has been pushed here).
  settings_.blocked_passage_on_sight = GapReportScope::Everywhere;
  Executive executive(settings_, vehicle_);
  const std::vector<Point> walls = doorWalls(0.72);
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, -1.5), waypoint(0.0, 1.5)};
  pose_ = Pose2{0.0, -1.5, 0.5 * M_PI};
  std::vector<std::int64_t> reported_us;
  std::optional<BlockedPassage> first;
  for (int cycle = 0; cycle < 125; ++cycle) {  // 2.5 s
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive.step(now_us_, inputs);
    if (output.blocked_passage) {
      reported_us.push_back(now_us_);
      if (!first) {
        first = output.blocked_passage;
      }
    }
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
  }
  ASSERT_TRUE(first);
  EXPECT_EQ(first->stalls, 0);
  EXPECT_EQ(first->goal_id, 5);
  EXPECT_LT((first->from - Point(0.0, -1.5)).norm(), 0.05) << first->text;
  EXPECT_NEAR(first->to.x(), 0.0, 1e-9);
  // 1 m beyond where the path meets the gap: up to 0.2 m before the wall's face at y = 0, where the posts
  // first lie within half the passable width of the path.
  EXPECT_GE(first->to.y(), 0.8) << first->text;
  EXPECT_LE(first->to.y(), 1.0) << first->text;
  EXPECT_NE(first->text.find("gap of 0.72 m"), std::string::npos) << first->text;
  // The same gap again only after gap_report_repeat_s (2 s): twice in 2.5 s.
  ASSERT_EQ(reported_us.size(), 2U);
  EXPECT_EQ(reported_us[0], now_us_ - 124 * kCycleUs);
  EXPECT_GE(static_cast<double>(reported_us[1] - reported_us[0]) * 1e-6, settings_.gap_report_repeat_s);
  EXPECT_LT(static_cast<double>(reported_us[1] - reported_us[0]) * 1e-6,
            settings_.gap_report_repeat_s + 0.05);
}

TEST_F(ExecutiveTest, AGapTheVehicleFitsThroughIsNotReportedOnSight)
{
  settings_.blocked_passage_on_sight = GapReportScope::Everywhere;
  Executive executive(settings_, vehicle_);
  const std::vector<Point> walls = doorWalls(1.0);
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, -1.5), waypoint(0.0, 1.5)};
  pose_ = Pose2{0.0, -1.5, 0.5 * M_PI};
  Inputs inputs = freshInputs(now_us_ + kCycleUs, path);
  inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_ + kCycleUs};
  EXPECT_FALSE(executive.step(now_us_ + kCycleUs, inputs).blocked_passage);
}

TEST_F(ExecutiveTest, OnlyAGapBesideAnObjectThisExecutivePushedIsReportedOnSightByDefault)
{
  // pushPath's object 9 is expected at (3.1, 0) after its push. Once the push has finished, a 0.72 m
  // gap across the rest of the path at x = 3.6, its posts 0.62 m from the object, is reported at once.
  // The same gap ahead of an executive that has pushed nothing is left to the follower and the stalls.
  ASSERT_EQ(settings_.blocked_passage_on_sight, GapReportScope::NearPushedObjects);
  Path path = pushPath();
  path.push_plans[0].controls[0].expected_object_pose = {3.1, 0.0, 0.0};
  std::vector<Point> gap_across_x;  // doorWalls turned to run along y at x = 3.6 .. 3.8
  for (const Point& point : doorWalls(0.72)) {
    gap_across_x.emplace_back(3.6 + point.y(), -point.x());
  }

  Executive pushed_nothing(settings_, vehicle_);
  pose_ = {2.4, 0.0, 0.0};
  Inputs inputs = freshInputs(now_us_ + kCycleUs, straightPath());
  inputs.path->value.waypoints = {waypoint(2.4, 0.0), waypoint(5.0, 0.0)};
  inputs.obstacles = Stamped<std::vector<Point>>{gap_across_x, now_us_ + kCycleUs};
  EXPECT_FALSE(pushed_nothing.step(now_us_ + kCycleUs, inputs).blocked_passage);

  pose_ = {-2.0, 0.0, 0.0};
  Output output;
  for (int cycle = 0; cycle < 3000 && output.status.pushes == 0; ++cycle) {
    output = run(1, path, executive_.mode() == Mode::Push ? 100.0 : 0.0);
    ASSERT_FALSE(output.blocked_passage) << "no walls yet";
  }
  ASSERT_EQ(output.status.pushes, 1) << output.status.reason;
  ASSERT_LT(pose_.x, 3.0) << "the vehicle is still before the gap";
  // The planner's next path, the object moved: from the vehicle on to the goal.
  Path replanned = straightPath(2);
  replanned.waypoints = {waypoint(pose_.x, pose_.y), waypoint(5.0, 0.0)};
  now_us_ += kCycleUs;
  inputs = freshInputs(now_us_, replanned);
  inputs.obstacles = Stamped<std::vector<Point>>{gap_across_x, now_us_};
  output = executive_.step(now_us_, inputs);
  ASSERT_TRUE(output.blocked_passage);
  EXPECT_EQ(output.blocked_passage->stalls, 0);
  EXPECT_NE(output.blocked_passage->text.find("gap of 0.72 m"), std::string::npos)
      << output.blocked_passage->text;
}

TEST_F(ExecutiveTest, StallingAgainAndAgainAtAGapTooNarrowReportsTheBlockedPassage)
{
  // The third stall within 1 m, toward the same waypoint, reports the passage (the report on sight off,
  // as where the obstacle points do not show the gap narrow).
  settings_.blocked_passage_on_sight = GapReportScope::Off;
  Executive executive(settings_, vehicle_);
  int stalls = 0;
  const std::optional<BlockedPassage> reported = driveAtNarrowGap(executive, 100, stalls);
  ASSERT_TRUE(reported) << stalls << " stalls, ended at (" << pose_.x << ", " << pose_.y << ")";
  // Reported on the cycle the third stall began (its back-off starts on the same cycle).
  EXPECT_EQ(stalls, settings_.blocked_passage_stalls);
  EXPECT_LT(pose_.y, 0.2) << "a 0.72 m gap cannot be driven through";
  EXPECT_EQ(reported->goal_id, 5);
  EXPECT_EQ(reported->stalls, settings_.blocked_passage_stalls);
  EXPECT_NEAR(reported->to.x(), 0.0, 1e-9);
  EXPECT_NEAR(reported->to.y(), 1.5, 1e-9);
  EXPECT_LT((reported->from - Point(0.0, -0.5)).norm(), 1.0) << reported->text;
  EXPECT_NE(reported->text.find("stalled 3 times"), std::string::npos) << reported->text;
}

TEST_F(ExecutiveTest, ABlockedPassageOnALongLegIsReportedTowardThePathPointAFewMetresAhead)
{
  // The planner seals the narrowest point between `from` and `to`: with the waypoint 20 m on, that
  // could be anywhere along the leg; 2.5 m along the path keeps it at the gap the vehicle stalled in.
  settings_.blocked_passage_on_sight = GapReportScope::Off;
  Executive executive(settings_, vehicle_);
  int stalls = 0;
  const std::optional<BlockedPassage> reported = driveAtNarrowGap(executive, 100, stalls, 20.0);
  ASSERT_TRUE(reported) << stalls << " stalls, ended at (" << pose_.x << ", " << pose_.y << ")";
  EXPECT_NEAR((reported->to - reported->from).norm(), 2.5, 1e-6) << reported->text;
  const Point toward_goal = (Point(0.0, 20.0) - reported->from).normalized();
  EXPECT_LT((reported->to - (reported->from + 2.5 * toward_goal)).norm(), 1e-6) << reported->text;
}

TEST_F(ExecutiveTest, BlockedPassageReportsCanBeTurnedOff)
{
  settings_.blocked_passage_stalls = 0;
  settings_.blocked_passage_on_sight = GapReportScope::Off;
  Executive executive(settings_, vehicle_);
  int stalls = 0;
  EXPECT_FALSE(driveAtNarrowGap(executive, 4, stalls));
  EXPECT_EQ(stalls, 4);
}

DoorDrive ExecutiveTest::driveThroughDoor(Executive& executive, const Pose2& start)
{
  const std::vector<Point> walls = doorWalls();
  Path path = straightPath();
  path.waypoints = {waypoint(start.x, start.y), waypoint(-0.15, -0.3), waypoint(1.8, 2.5),
                    waypoint(3.5, 3.0)};
  pose_ = start;
  DoorDrive result;
  bool was_stalled = false;
  const std::int64_t began_us = now_us_;
  for (int cycle = 0; cycle < 3000; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive.step(now_us_, inputs);
    result.last_reason = output.status.reason;
    const bool stalled = output.status.reason.find("stalled for") != std::string::npos;
    result.stalls += stalled && !was_stalled ? 1 : 0;
    was_stalled = stalled;
    result.doorway_cycles += output.status.reason.rfind("doorway at", 0) == 0 ? 1 : 0;
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
    for (const Point& point : walls) {
      result.least_clearance_m =
          std::min(result.least_clearance_m, executive.settings().follower.footprint.distance(pose_, point));
    }
    if (pose_.y > 1.2) {
      result.seconds_through = static_cast<double>(now_us_ - began_us) * 1e-6;
      break;
    }
  }
  return result;
}

TEST_F(ExecutiveTest, ADoorBarelyWiderThanTheVehicleIsDrivenAsAStraightRun)
{
  // Below the office's 1.0 m door, 2.5 m to the left of it, heading along the corridor.
  const DoorDrive run = driveThroughDoor(executive_, Pose2{-2.5, -1.3, 0.0});
  EXPECT_GT(run.seconds_through, 0.0) << run.last_reason;
  EXPECT_LT(run.seconds_through, 10.0) << run.last_reason;  // 8.9 s
  EXPECT_EQ(run.stalls, 0);
  EXPECT_GT(run.doorway_cycles, 0);
  EXPECT_GE(run.least_clearance_m, 0.1);  // 0.15 m either side when centred and square
}

TEST_F(ExecutiveTest, WithoutDoorwayRunsTheFollowerWedgesInTheSameDoor)
{
  // The control for the test above: following alone turns into the door at a slant and stalls.
  settings_.doorway.enabled = false;
  Executive following(settings_, vehicle_);
  const DoorDrive run = driveThroughDoor(following, Pose2{-2.5, -1.3, 0.0});
  EXPECT_EQ(run.doorway_cycles, 0);
  EXPECT_GE(run.stalls, 1);
  EXPECT_GT(run.seconds_through, 12.0);  // 13.8 s
}

TEST_F(ExecutiveTest, WedgedAtASlantInADoorTurnsToFaceItAndDrivesThrough)
{
  // The office world's door: 1.0 m wide (x -0.5 .. 0.5) in a 0.2 m wall at y 0 .. 0.2, the vehicle just
  // below it turned 35 degrees to the left, the next waypoint beyond it. Following alone dithered here
  // for 100 s; after the stall's straight escape the vehicle turns on the spot to face the door, then
  // drives through.
  const std::vector<Point> walls = doorWalls();
  Path path = straightPath();
  path.waypoints = {waypoint(0.0, -0.28), waypoint(0.0, 0.47), waypoint(0.0, 2.0)};
  pose_ = Pose2{-0.13, -0.48, 125.0 * M_PI / 180.0};
  bool turned = false;
  bool through = false;
  std::string last_reason;
  for (int cycle = 0; cycle < 3000 && !through; ++cycle) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path);
    inputs.obstacles = Stamped<std::vector<Point>>{walls, now_us_};
    const Output output = executive_.step(now_us_, inputs);
    last_reason = output.status.reason;
    turned = turned || output.status.reason.find("turning on the spot") != std::string::npos;
    pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
    through = pose_.y > 0.9;
  }
  EXPECT_TRUE(through) << "ended at (" << pose_.x << ", " << pose_.y << ", " << pose_.heading
                       << "): " << last_reason;
  EXPECT_TRUE(turned);
}

TEST_F(ExecutiveTest, AccelerationIsLimited)
{
  run(1, straightPath());
  const Output second = run(1, straightPath());
  EXPECT_LE(second.command.linear, vehicle_.max_linear_acceleration * kCycleUs * 1e-6 + 1e-12);
}

TEST_F(ExecutiveTest, InvalidPathStopsWithReason)
{
  Path path = straightPath();
  path.valid = false;
  path.waypoints.clear();
  const Output output = run(1, path);
  EXPECT_EQ(output.status.mode, Mode::Stop);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_NE(output.status.reason.find("no path to goal 5"), std::string::npos) << output.status.reason;
  const Output recovered = run(1, straightPath(2));
  EXPECT_EQ(recovered.status.mode, Mode::Follow);
}

TEST_F(ExecutiveTest, EStopStopsAtOnceAndReleases)
{
  const Output moving = run(30, straightPath());
  ASSERT_GT(moving.command.linear, 0.0);
  now_us_ += kCycleUs;
  Inputs inputs = freshInputs(now_us_, straightPath());
  inputs.e_stop = Stamped<EStopSignal>{EStopSignal{true, "operator", "test"}, now_us_};
  const Output stopped = executive_.step(now_us_, inputs);
  EXPECT_EQ(stopped.status.mode, Mode::EStop);
  EXPECT_TRUE(stopped.command.isZero());
  EXPECT_DOUBLE_EQ(stopped.wheels.left, 0.0);
  EXPECT_NE(stopped.status.reason.find("operator"), std::string::npos);

  now_us_ += kCycleUs;
  inputs = freshInputs(now_us_, straightPath());
  inputs.e_stop = Stamped<EStopSignal>{EStopSignal{false, "operator", "released"}, now_us_};
  const Output released = executive_.step(now_us_, inputs);
  EXPECT_EQ(released.status.mode, Mode::Follow);
}

/// Which input to let go stale; its threshold; its bit.
struct StaleCase {
  const char* name;
  double threshold_s;
  std::int32_t bit;
};

class StaleInputTest : public ExecutiveTest, public ::testing::WithParamInterface<StaleCase> {};

TEST_P(StaleInputTest, ZeroCommandWithinOneCycleAfterThreshold)
{
  const StaleCase stale = GetParam();
  const Output moving = run(30, straightPath());
  ASSERT_GT(moving.command.linear, 0.0);
  const std::int64_t last_fresh_us = now_us_;

  // Keep everything else fresh; hold the chosen input's stamp.
  const auto inputs_at = [&](std::int64_t now_us) {
    Inputs inputs = freshInputs(now_us, straightPath());
    const std::string name = stale.name;
    if (name == "pose") {
      inputs.pose->utime = last_fresh_us;
    } else if (name == "path") {
      inputs.path->utime = last_fresh_us;
    } else if (name == "force") {
      inputs.force->utime = last_fresh_us;
    } else if (name == "obstacles") {
      inputs.obstacles->utime = last_fresh_us;
    } else {
      inputs.motor->utime = last_fresh_us;
    }
    return inputs;
  };
  const std::int64_t threshold_us = static_cast<std::int64_t>(std::llround(stale.threshold_s * 1e6));
  const Output before =
      executive_.step(last_fresh_us + threshold_us, inputs_at(last_fresh_us + threshold_us));
  EXPECT_EQ(before.status.mode, Mode::Follow);
  EXPECT_FALSE(before.command.isZero());
  const std::int64_t after_us = last_fresh_us + threshold_us + kCycleUs;
  const Output after = executive_.step(after_us, inputs_at(after_us));
  EXPECT_EQ(after.status.mode, Mode::Stop);
  EXPECT_TRUE(after.command.isZero());
  EXPECT_EQ(after.status.stale, stale.bit);
  EXPECT_NE(after.status.reason.find(stale.name), std::string::npos) << after.status.reason;

  // Fresh again: the vehicle goes on.
  const Output resumed = run(1, straightPath());
  EXPECT_EQ(resumed.status.mode, Mode::Follow);
  EXPECT_EQ(resumed.status.stale, 0);
}

INSTANTIATE_TEST_SUITE_P(
    EachInput, StaleInputTest,
    ::testing::Values(StaleCase{"pose", 0.1, kStalePose}, StaleCase{"path", 1.0, kStalePath},
                      StaleCase{"force", 0.1, kStaleForce}, StaleCase{"motor", 0.3, kStaleMotor},
                      // A frozen or unplugged lidar: the vehicle stops instead of following blind.
                      StaleCase{"obstacles", 0.5, kStaleObstacles}),
    [](const ::testing::TestParamInfo<StaleCase>& param_info) { return std::string(param_info.param.name); });

TEST_F(ExecutiveTest, MotorFaultStopsWithMotorReason)
{
  run(10, straightPath());
  now_us_ += kCycleUs;
  Inputs inputs = freshInputs(now_us_, straightPath());
  inputs.motor->value = MotorReading{true, true, "EMCY 0x2310 over-current"};
  const Output output = executive_.step(now_us_, inputs);
  EXPECT_EQ(output.status.mode, Mode::Stop);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_NE(output.status.reason.find("over-current"), std::string::npos) << output.status.reason;
}

TEST_F(ExecutiveTest, FaultyForceSensorStops)
{
  run(10, straightPath());
  now_us_ += kCycleUs;
  Inputs inputs = freshInputs(now_us_, straightPath());
  inputs.force->value.faulty = true;
  const Output output = executive_.step(now_us_, inputs);
  EXPECT_EQ(output.status.mode, Mode::Stop);
  EXPECT_EQ(output.status.stale, kStaleForce);
}

TEST_F(ExecutiveTest, FollowApproachPushFollowArrive)
{
  // The bumper feels 100 N while pushing (the object slides as planned), nothing otherwise. The vehicle
  // starts 3 m before the topological waypoint, beyond the switch radius.
  pose_ = {-2.0, 0.0, 0.0};
  const Path path = pushPath();
  Output output;
  int pushes_seen = 0;
  for (int cycle = 0; cycle < 3000 && output.status.mode != Mode::Arrived; ++cycle) {
    const double force = executive_.mode() == Mode::Push ? 100.0 : 0.0;
    output = run(1, path, force);
    if (output.status.mode == Mode::Push) {
      EXPECT_EQ(output.status.target_object_id, 9);
    }
    pushes_seen = output.status.pushes;
  }
  EXPECT_EQ(output.status.mode, Mode::Arrived);
  EXPECT_TRUE(visited(Mode::Follow));
  EXPECT_TRUE(visited(Mode::Approach));
  EXPECT_TRUE(visited(Mode::Push));
  EXPECT_EQ(pushes_seen, 1);
  EXPECT_TRUE(events_.empty());  // cost as planned: nothing to report
  // In order: follow, approach, push, follow again, arrived.
  const auto first = [this](Mode mode) {
    return std::find(modes_.begin(), modes_.end(), mode) - modes_.begin();
  };
  EXPECT_LT(first(Mode::Follow), first(Mode::Approach));
  EXPECT_LT(first(Mode::Approach), first(Mode::Push));
  EXPECT_LT(first(Mode::Push), first(Mode::Arrived));
}

TEST_F(ExecutiveTest, UnpushableObjectWaitsForReplan)
{
  const Path path = pushPath(1, now_us_);
  // Drive to the contact first.
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, path);
  }
  ASSERT_EQ(executive_.mode(), Mode::Push);
  // The object does not move: the vehicle stalls at the maximum force.
  const double stall_force = 0.95 * vehicle_.maxPushForce();
  Output output;
  int cycles_to_event = 0;
  while (events_.empty() && cycles_to_event < 500) {
    output = run(1, path, stall_force, true);
    ++cycles_to_event;
  }
  ASSERT_EQ(events_.size(), 1u);
  EXPECT_FALSE(events_[0].pushable);
  EXPECT_EQ(events_[0].object_id, 9);
  EXPECT_EQ(events_[0].reason, AffordanceReason::NoMotion);
  EXPECT_NEAR(cycles_to_event * kCycleUs * 1e-6, settings_.tactile.no_motion_time_s, 0.05);
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_EQ(output.status.replans, 1);

  // A resend of the old plan does not end the wait; a path planned after the event does.
  const Output still = run(5, pushPath(2, now_us_ - 10 * kCycleUs), 0.0);
  EXPECT_EQ(still.status.mode, Mode::ReplanWait);
  Path detour = straightPath(3, now_us_ + kCycleUs);
  detour.waypoints = {waypoint(pose_.x, pose_.y), waypoint(pose_.x, 2.0), waypoint(5.0, 2.0)};
  const Output replanned = run(1, detour);
  EXPECT_EQ(replanned.status.mode, Mode::Follow);
  EXPECT_EQ(replanned.status.replans, 1);
}

TEST_F(ExecutiveTest, AnObjectJammedAfterSlidingStaysPushableOnceThenIsUnpushable)
{
  const Path path = pushPath(1, now_us_);
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, path);
  }
  ASSERT_EQ(executive_.mode(), Mode::Push);
  // 1.5 s at the planned 100 N (0.45 m at 0.3 m/s), then the object catches a wall: maximum force, no
  // motion.
  run(75, path, 100.0);
  ASSERT_TRUE(events_.empty());
  const double stall_force = 0.95 * vehicle_.maxPushForce();
  Output output;
  for (int cycle = 0; cycle < 500 && events_.empty(); ++cycle) {
    output = run(1, path, stall_force, true);
  }
  ASSERT_EQ(events_.size(), 1u);
  EXPECT_EQ(events_[0].reason, AffordanceReason::Jammed);
  EXPECT_TRUE(events_[0].pushable);
  // What it slid at, not the 522 N it was held at (one cycle of travel at the higher force counts).
  EXPECT_NEAR(events_[0].push_force_n, 100.0, 10.0);
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);

  // The planner plans the object again from where it stands; it jams again: now it is unpushable.
  Path again = pushPath(2, now_us_ + kCycleUs);
  again.push_plans[0].contact_pose = pose_;
  again.push_plans[0].controls[0].expected_vehicle_pose = {pose_.x + 0.9, 0.0, 0.0};
  again.waypoints = {waypoint(pose_.x, 0.0), waypoint(pose_.x + 0.1, 0.0, WaypointKind::Topological, 9, 0),
                     waypoint(pose_.x + 1.0, 0.0, WaypointKind::Push, 9, 0), waypoint(5.0, 0.0)};
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, again);
  }
  ASSERT_EQ(executive_.mode(), Mode::Push);
  run(75, again, 100.0);
  for (int cycle = 0; cycle < 500 && events_.size() < 2; ++cycle) {
    output = run(1, again, stall_force, true);
  }
  ASSERT_EQ(events_.size(), 2u);
  EXPECT_EQ(events_[1].reason, AffordanceReason::NoMotion);
  EXPECT_FALSE(events_[1].pushable);
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);
}

TEST_F(ExecutiveTest, HigherCostWhilePushingWaitsForReplan)
{
  const Path path = pushPath(1, now_us_);
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, path);
  }
  ASSERT_EQ(executive_.mode(), Mode::Push);
  Output output;
  for (int cycle = 0; cycle < 300 && events_.empty(); ++cycle) {
    output = run(1, path, 300.0);  // three times the planned force, still sliding
  }
  ASSERT_EQ(events_.size(), 1u);
  EXPECT_TRUE(events_[0].pushable);
  EXPECT_EQ(events_[0].reason, AffordanceReason::CostHigher);
  EXPECT_NEAR(events_[0].measured_cost, 1.5 + 0.9 * 3.0, 0.05);  // travel + planned push part x 3
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);
}

TEST_F(ExecutiveTest, ReplanWaitTimesOutIntoStop)
{
  const Path path = pushPath(1, now_us_);
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, path);
  }
  for (int cycle = 0; cycle < 500 && executive_.mode() != Mode::ReplanWait; ++cycle) {
    run(1, path, vehicle_.maxPushForce(), true);
  }
  ASSERT_EQ(executive_.mode(), Mode::ReplanWait);
  const int timeout_cycles = static_cast<int>(settings_.replan_timeout_s / (kCycleUs * 1e-6)) + 2;
  const Output output = run(timeout_cycles, path);
  EXPECT_EQ(output.status.mode, Mode::Stop);
  EXPECT_NE(output.status.reason.find("no replanned path"), std::string::npos) << output.status.reason;
}

TEST_F(ExecutiveTest, StaleInputDuringPushResumesThroughFollow)
{
  const Path path = pushPath();
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, path);
  }
  ASSERT_EQ(executive_.mode(), Mode::Push);
  now_us_ += kCycleUs;
  Inputs inputs = freshInputs(now_us_, path, 100.0);
  inputs.pose->utime = now_us_ - 1'000'000;
  EXPECT_EQ(executive_.step(now_us_, inputs).status.mode, Mode::Stop);
  // Shoved 0.3 m sideways while stopped: out of the push lane, so the push may not simply carry on.
  pose_.y += 0.3;
  const Output resumed = run(1, path, 100.0);
  EXPECT_NE(resumed.status.mode, Mode::Push) << resumed.status.reason;
  EXPECT_NE(resumed.status.mode, Mode::Stop);
}

TEST_F(ExecutiveTest, AStuckPushUnderPoseJitterWithSlippingWheelsIsFoundUnpushableWithinTheWindow)
{
  // A state estimator's pose (2 cm, 0.003 rad of jitter per sample) and wheel odometry: the drives turn
  // at the commanded speed while the vehicle stands against an object it cannot move.
  const Path path = pushPath(1, now_us_);
  for (int cycle = 0; cycle < 3000 && executive_.mode() != Mode::Push; ++cycle) {
    run(1, path);
  }
  ASSERT_EQ(executive_.mode(), Mode::Push);
  std::mt19937 random(5);
  std::normal_distribution<double> position(0.0, 0.02);
  std::normal_distribution<double> heading(0.0, 0.003);
  const double stall_force = 0.95 * vehicle_.maxPushForce();
  VelocityCommand command;
  int cycles_to_event = 0;
  Output output;
  while (events_.empty() && cycles_to_event < 500) {
    now_us_ += kCycleUs;
    Inputs inputs = freshInputs(now_us_, path, stall_force);
    const double dx = position(random);
    const double dy = position(random);
    inputs.pose->value = Pose2{pose_.x + dx, pose_.y + dy, pose_.heading + heading(random)};
    inputs.odometry =
        Stamped<OdometryReading>{OdometryReading{command.linear, command.angular, true}, now_us_};
    output = executive_.step(now_us_, inputs);
    command = output.command;
    if (output.affordance) {
      events_.push_back(*output.affordance);
    }
    ++cycles_to_event;
  }
  ASSERT_EQ(events_.size(), 1u) << output.status.reason;
  EXPECT_EQ(events_[0].reason, AffordanceReason::NoMotion);
  EXPECT_FALSE(events_[0].pushable);
  EXPECT_LE(cycles_to_event * kCycleUs * 1e-6, settings_.tactile.no_motion_time_s + 0.05);
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);
}

}  // namespace
}  // namespace ifar::executive
