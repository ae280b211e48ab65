// Approach and push with obstacle points: the returns on the object being pushed do not stop the
// vehicle, anything else in the way of a creep or push does.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "executive/kinematics/angle.hpp"
#include "executive/modes/executive.hpp"
#include "tests/unit/executive/simulation.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;
using geometry::Pose2;

constexpr std::int64_t kCycleUs = 20'000;  // 50 Hz
constexpr double kObjectHalfSide = 0.3;    // a 0.6 m box
const Point kObjectStart(2.25, 0.0);       // its face touches the bumper at the contact pose (1.5, 0)

Waypoint waypoint(double x, WaypointKind kind, std::int64_t object_id = -1, int plan_index = -1)
{
  Waypoint result;
  result.position = Point(x, 0.0);
  result.kind = kind;
  result.object_id = object_id;
  result.push_plan_index = plan_index;
  return result;
}

/// Object 9 pushed 0.9 m along +x from the contact pose (1.5, 0): its centroid goes (2.25, 0) -> (3.15, 0).
Path pushPath()
{
  Path path;
  path.goal_id = 5;
  path.sequence = 1;
  path.valid = true;
  PushPlan plan;
  plan.object_id = 9;
  plan.contact_pose = {1.5, 0.0, 0.0};
  PushControl control;
  control.linear_velocity = 0.3;
  control.duration_s = 3.0;
  control.expected_vehicle_pose = {2.4, 0.0, 0.0};
  control.expected_object_pose = {3.15, 0.0, 0.0};
  plan.controls.push_back(control);
  plan.expected_force_n = 100.0;
  plan.push_distance_m = 0.9;
  path.push_plans.push_back(plan);
  path.waypoints = {waypoint(0.0, WaypointKind::Free), waypoint(0.5, WaypointKind::Topological, 9, 0),
                    waypoint(3.5, WaypointKind::Push, 9, 0), waypoint(6.0, WaypointKind::Free)};
  return path;
}

/// Points every 5 cm on the outline of the box centred at `centre`.
std::vector<Point> boxReturns(const Point& centre)
{
  std::vector<Point> points;
  for (int step = 0; step <= 12; ++step) {
    const double along = -kObjectHalfSide + step * 0.05;
    points.emplace_back(centre.x() - kObjectHalfSide, centre.y() + along);
    points.emplace_back(centre.x() + kObjectHalfSide, centre.y() + along);
    points.emplace_back(centre.x() + along, centre.y() - kObjectHalfSide);
    points.emplace_back(centre.x() + along, centre.y() + kObjectHalfSide);
  }
  return points;
}

/// The executive gave the plan of object 9 up with `text` and waits for the replan, standing.
void expectPlanGivenUp(const Output& output, const std::optional<AffordanceEvent>& event,
                       const std::string& text)
{
  ASSERT_TRUE(event) << output.status.reason;
  EXPECT_EQ(event->object_id, 9);
  // Standing still is no force evidence: the object stays pushable, the contact is reported not reached.
  EXPECT_TRUE(event->pushable);
  EXPECT_EQ(event->reason, AffordanceReason::ContactNotReached);
  EXPECT_EQ(event->text, text);
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);
  EXPECT_TRUE(output.command.isZero());
}

class ExecutivePushObstaclesTest : public ::testing::Test {
 protected:
  ExecutivePushObstaclesTest() : executive_(settings_, vehicle_) {}

  /// One cycle: the object's returns (the bumper pushes it along +x) plus `others`; 100 N on the
  /// bumper while pushing.
  Output cycle(const std::vector<Point>& others, std::optional<double> force_n = std::nullopt)
  {
    now_us_ += kCycleUs;
    if (executive_.mode() == Mode::Push && !force_n) {
      // The bumper (0.45 m ahead of the pose) pushes the box's near face; backing off leaves it.
      object_.x() = std::max(object_.x(), pose_.x + 0.45 + kObjectHalfSide);
    }
    std::vector<Point> points = boxReturns(object_);
    points.insert(points.end(), others.begin(), others.end());
    const bool pushing = executive_.mode() == Mode::Push;
    Inputs inputs;
    inputs.pose = Stamped<Pose2>{pose_, now_us_};
    inputs.path = Stamped<Path>{path_, now_us_};
    inputs.force =
        Stamped<ForceReading>{ForceReading{force_n.value_or(pushing ? 100.0 : 0.0), false}, now_us_};
    inputs.motor = Stamped<MotorReading>{MotorReading{true, false, ""}, now_us_};
    inputs.obstacles = Stamped<std::vector<Point>>{points, now_us_};
    Output output = executive_.step(now_us_, inputs);
    if (!held_ && !(force_n && output.command.linear > 0.0)) {  // a stalling force stops forward motion
      pose_ = testing::drive(pose_, output.command, kCycleUs * 1e-6);
    }
    return output;
  }

  /// Pushes against an object that will not move until the executive waits for a replan (ReplanWait
  /// in the last output, unless it never got to push).
  Output pushUntilTheObjectStalls()
  {
    Output output;
    for (int index = 0; index < 500 && output.status.mode != Mode::Push; ++index) {
      output = cycle({});
    }
    for (int index = 0; index < 500 && output.status.mode == Mode::Push; ++index) {
      output = cycle({}, 0.95 * vehicle_.maxPushForce());
    }
    return output;
  }

  /// The replanned path: from where the vehicle stalled away to its left (+y), pushing nothing.
  void replanLeftOf(const Point& stalled)
  {
    path_.sequence = 2;
    path_.utime = now_us_ + kCycleUs;
    path_.push_plans.clear();
    path_.waypoints = {waypoint(stalled.x(), WaypointKind::Free), waypoint(6.0, WaypointKind::Free)};
    path_.waypoints[1].position = Point(stalled.x(), 2.0);
  }

  ExecutiveSettings settings_;
  common::VehicleSettings vehicle_;
  Executive executive_;
  bool held_ = false;  // the vehicle does not move whatever it is commanded
  Path path_ = pushPath();
  Pose2 pose_{0.85, 0.0, 0.0};  // in the push lane behind the contact pose: no collision-free leg
  Point object_ = kObjectStart;
  std::int64_t now_us_ = 1'000'000'000;
};

TEST_F(ExecutivePushObstaclesTest, ObjectReturnsDoNotStopApproachOrPush)
{
  bool approached = false;
  bool pushed = false;
  Output output;
  for (int index = 0; index < 1500 && output.status.pushes == 0; ++index) {
    output = cycle({});
    approached = approached || output.status.mode == Mode::Approach;
    pushed = pushed || output.status.mode == Mode::Push;
    ASSERT_EQ(output.status.reason.find("stopped"), std::string::npos)
        << "cycle " << index << ": " << output.status.reason;
    if (output.status.mode == Mode::Approach || output.status.mode == Mode::Push) {
      const std::optional<ObjectObservation> expected = executive_.pushedObjectEstimate();
      ASSERT_TRUE(expected.has_value());
      EXPECT_EQ(expected->object_id, 9);
    }
  }
  EXPECT_TRUE(approached);
  EXPECT_TRUE(pushed);
  EXPECT_EQ(output.status.pushes, 1);
  EXPECT_NEAR(object_.x(), 3.15, 0.1);  // pushed as planned
}

TEST_F(ExecutivePushObstaclesTest, WithoutTheObjectRadiusTheObjectWouldStopTheCreep)
{
  // The control for the test above: the same run with the object's returns counted as obstacles.
  settings_.pushed_object.radius_m = 0.01;
  executive_ = Executive(settings_, vehicle_);
  Output output;
  for (int index = 0; index < 300 && output.status.reason.find("stopped: obstacle") == std::string::npos;
       ++index) {
    output = cycle({});
  }
  EXPECT_EQ(output.status.mode, Mode::Approach);
  EXPECT_NE(output.status.reason.find("stopped: obstacle"), std::string::npos) << output.status.reason;
}

TEST_F(ExecutivePushObstaclesTest, AContactThatCannotBeReachedIsReportedAndReplanned)
{
  // Stopped short of the contact for twice stall_timeout_s (the object's returns counted as obstacles, as
  // above): the plan cannot be carried out, which the planner hears as an affordance update.
  settings_.pushed_object.radius_m = 0.01;
  executive_ = Executive(settings_, vehicle_);
  Output output;
  std::optional<AffordanceEvent> event;
  int cycles = 0;  // since the guard stopped the creep
  for (int index = 0; index < 800 && !event; ++index) {
    output = cycle({});
    event = output.affordance;
    cycles += cycles > 0 || output.status.reason.find("stopped: obstacle") != std::string::npos ? 1 : 0;
  }
  ASSERT_TRUE(event) << output.status.reason;
  EXPECT_EQ(event->object_id, 9);
  // A light box the vehicle could not get to stays pushable: only force evidence says otherwise.
  EXPECT_TRUE(event->pushable);
  EXPECT_EQ(event->reason, AffordanceReason::ContactNotReached);
  EXPECT_NE(event->text.find("contact not reached"), std::string::npos) << event->text;
  EXPECT_EQ(output.status.mode, Mode::ReplanWait);
  EXPECT_TRUE(output.command.isZero());
  // Twice the stall time after the guard stopped the creep (the creep's last centimetres count too).
  EXPECT_GE(cycles * kCycleUs * 1e-6, 2.0 * settings_.stall_timeout_s - 1.0);
  EXPECT_LE(cycles * kCycleUs * 1e-6, 2.0 * settings_.stall_timeout_s + 0.1);
}

TEST_F(ExecutivePushObstaclesTest, AnApproachStuckOnItsWayToTheStandOffPointEscapesOnceAndPushes)
{
  // Facing a wall 0.1 m ahead of the bumper, the stand-off point (0.9, 0) to the right: no arc is free
  // and the footprint's corners (0.57 m from the pose) cannot turn on the spot. Standing still there says
  // nothing about the object; the executive backs off, turns and approaches again instead of reporting it
  // unpushable.
  pose_ = Pose2{0.2, 0.0, kPi / 2.0};
  std::vector<Point> wall;
  for (int index = 0; index <= 70; ++index) {  // x from -1.5 to 2.0 every 5 cm
    wall.emplace_back(-1.5 + 0.05 * index, 0.55);
  }
  Output output;
  bool escaped = false;
  for (int index = 0; index < 3000 && output.status.pushes == 0; ++index) {
    output = cycle(wall);
    ASSERT_FALSE(output.affordance.has_value()) << "cycle " << index << ": " << output.affordance->text;
    escaped = escaped || output.status.reason.find("stalled") != std::string::npos;
  }
  EXPECT_TRUE(escaped) << output.status.reason;
  EXPECT_EQ(output.status.pushes, 1) << output.status.reason;
  EXPECT_NEAR(object_.x(), 3.15, 0.1);
}

TEST_F(ExecutivePushObstaclesTest, AnApproachWhoseTurnAtTheStandOffPointIsBlockedBacksUpAndPushes)
{
  // At the stand-off point (0.9, 0) but facing across the lane, a wall 0.1 m ahead of the bumper: the
  // turn on the spot to the lane's heading sweeps the front corners 0.57 m out, and the guard stops it.
  // (A Willow approach ended so: the leg's last decimetres turned the vehicle across a corridor, and the
  // stand-still reported the object unpushable.) The vehicle backs straight up until the turn is free,
  // turns, and the creep takes out the offset on its way to the contact.
  pose_ = Pose2{0.9, 0.0, kPi / 2.0};
  std::vector<Point> wall;
  for (int index = 0; index <= 70; ++index) {  // x from -1.5 to 2.0 every 5 cm
    wall.emplace_back(-1.5 + 0.05 * index, 0.55);
  }
  Output output;
  double backed_to = 0.0;
  for (int index = 0; index < 3000 && output.status.pushes == 0; ++index) {
    output = cycle(wall);
    ASSERT_FALSE(output.affordance.has_value()) << "cycle " << index << ": " << output.affordance->text;
    ASSERT_EQ(output.status.reason.find("stalled"), std::string::npos)
        << "cycle " << index << ": " << output.status.reason;
    if (output.status.reason.find("backing up to turn to the lane's heading") != std::string::npos) {
      backed_to = pose_.y;
    }
  }
  // Backed up 5-15 cm: the turn then clears the wall by the guard's 5 cm and a few more.
  EXPECT_LT(backed_to, -0.05);
  EXPECT_GT(backed_to, -0.15);
  EXPECT_EQ(output.status.pushes, 1) << output.status.reason;
  EXPECT_NEAR(object_.x(), 3.15, 0.1);
}

TEST_F(ExecutivePushObstaclesTest, APushTheGuardHoldsIsReportedAndReplanned)
{
  // The push turns left (0.3 rad/s), which swings the rear right into a post 4 cm beside the rear
  // corner, first seen when the push starts: the guard holds the vehicle, no force rises, and the
  // tactile monitor has nothing to say. It stood there for good before (as in bench Willow t8 beside a
  // door post); now twice stall_timeout_s without motion is reported like a contact not reached.
  PushControl& control = path_.push_plans.front().controls.front();
  control.angular_velocity = 0.3;
  control.expected_vehicle_pose = {1.5 + std::sin(0.9), 1.0 - std::cos(0.9), 0.9};
  control.expected_object_pose = {control.expected_vehicle_pose.x + 0.75 * std::cos(0.9),
                                  control.expected_vehicle_pose.y + 0.75 * std::sin(0.9), 0.9};
  const std::vector<Point> post = {Point(1.1, -0.39)};
  Output output;
  std::optional<AffordanceEvent> event;
  int pushing_cycles = 0;
  for (int index = 0; index < 3000 && !event; ++index) {
    const bool pushing = executive_.mode() == Mode::Push;
    output = cycle(pushing ? post : std::vector<Point>{});
    event = output.affordance;
    pushing_cycles += pushing ? 1 : 0;
  }
  expectPlanGivenUp(output, event, "object 9: push held by the guard: no motion for 3.0 s");
  // Held from the push's first cycles: reported twice the stall time later.
  EXPECT_NEAR(pushing_cycles * kCycleUs * 1e-6, 2.0 * settings_.stall_timeout_s, 0.3);
}

TEST_F(ExecutivePushObstaclesTest, AnApproachStuckTwiceOnItsWayReportsTheContactAsNotReached)
{
  // Boxed in on all sides, 0.1 m from the footprint, short of the stand-off point: the one escape cannot
  // help, and the second stand-still is reported as before.
  pose_ = Pose2{0.2, 0.0, kPi / 2.0};
  std::vector<Point> box;
  for (int index = 0; index <= 40; ++index) {  // -1.0 to 1.0 every 5 cm
    const double along = -1.0 + 0.05 * index;
    box.emplace_back(0.2 + along, 0.55);
    box.emplace_back(0.2 + along, -0.55);
    box.emplace_back(-0.25, along);
    box.emplace_back(0.65, along);
  }
  Output output;
  std::optional<AffordanceEvent> event;
  for (int index = 0; index < 3000 && !event; ++index) {
    output = cycle(box);
    event = output.affordance;
  }
  ASSERT_TRUE(event) << output.status.reason;
  EXPECT_TRUE(event->pushable);
  EXPECT_EQ(event->reason, AffordanceReason::ContactNotReached);
  EXPECT_NE(event->text.find("contact not reached"), std::string::npos) << event->text;
  EXPECT_EQ(output.status.pushes, 0);
}

TEST_F(ExecutivePushObstaclesTest, AContactSwitchThatGetsNowhereIsReportedAsNotReached)
{
  // After the first push the plan switches to the box's left face (edge 3), driving round it like a first
  // approach. A vehicle that gets nowhere there (held in place from the switch's first cycle: boxed in,
  // as one was beside a box in a Willow corridor) stood until the run timed out; now twice
  // stall_timeout_s without motion reports the contact as not reached, as on a first approach.
  PushPlan& plan = path_.push_plans.front();
  PushControl switch_contact;
  switch_contact.kind = PushControlKind::SwitchContact;
  switch_contact.contact_edge = 3;
  switch_contact.expected_vehicle_pose = {3.15, 1.2, -kPi / 2.0};
  switch_contact.expected_object_pose = plan.controls.front().expected_object_pose;
  PushControl sideways = plan.controls.front();
  sideways.contact_edge = 3;
  sideways.expected_vehicle_pose = {3.15, 0.6, -kPi / 2.0};
  sideways.expected_object_pose = {3.15, -0.3, 0.0};
  plan.controls.push_back(switch_contact);
  plan.controls.push_back(sideways);

  Output output;
  std::optional<AffordanceEvent> event;
  int held_cycles = 0;
  for (int index = 0; index < 3000 && !event; ++index) {
    output = cycle({});
    event = output.affordance;
    if (held_cycles > 0 || output.status.reason.find("switching to contact edge 3") != std::string::npos) {
      held_ = true;
      ++held_cycles;
    }
  }
  expectPlanGivenUp(output, event,
                    "object 9: contact edge 3 not reached: no motion for 3.0 s on the way to it");
  EXPECT_NEAR(held_cycles * kCycleUs * 1e-6, 2.0 * settings_.stall_timeout_s, 0.1);
}

TEST_F(ExecutivePushObstaclesTest, APushUnderWayFinishesWhenTheReplannedPathDropsIt)
{
  Output output;
  for (int index = 0; index < 500 && output.status.mode != Mode::Push; ++index) {
    output = cycle({});
  }
  ASSERT_EQ(output.status.mode, Mode::Push);
  // The planner replans for the same goal without the push (the moved box no longer blocks it).
  path_.sequence = 2;
  path_.utime = now_us_;
  path_.push_plans.clear();
  path_.waypoints = {waypoint(2.0, WaypointKind::Free), waypoint(2.5, WaypointKind::Free),
                     waypoint(6.0, WaypointKind::Free)};
  std::vector<Mode> modes;
  for (int index = 0; index < 1500 && output.status.pushes == 0; ++index) {
    output = cycle({});
    modes.push_back(output.status.mode);
  }
  EXPECT_EQ(output.status.pushes, 1);
  // Pushing went on to the release, then the new path was followed.
  const auto first_follow = std::find(modes.begin(), modes.end(), Mode::Follow);
  EXPECT_TRUE(std::all_of(modes.begin(), first_follow, [](Mode mode) { return mode == Mode::Push; }));
  EXPECT_NEAR(object_.x(), 3.15, 0.1);
}

TEST_F(ExecutivePushObstaclesTest, APushUnderWayFinishesWhenTheReplanFindsNoPathThenTheVehicleStops)
{
  Output output;
  for (int index = 0; index < 500 && output.status.mode != Mode::Push; ++index) {
    output = cycle({});
  }
  ASSERT_EQ(output.status.mode, Mode::Push);
  // The object on the move closes the passage in one frame: the planner reports no path.
  const Path pushing = path_;
  path_.sequence = 2;
  path_.utime = now_us_;
  path_.valid = false;
  path_.push_plans.clear();
  path_.waypoints.clear();
  std::vector<Mode> modes;
  for (int index = 0; index < 1500 && output.status.pushes == 0; ++index) {
    output = cycle({});
    modes.push_back(output.status.mode);
  }
  EXPECT_EQ(output.status.pushes, 1);
  EXPECT_NEAR(object_.x(), 3.15, 0.1);
  const auto first_other =
      std::find_if(modes.begin(), modes.end(), [](Mode mode) { return mode != Mode::Push; });
  EXPECT_EQ(first_other, modes.end() - 1);  // pushed through to the release
  EXPECT_EQ(output.status.mode, Mode::Stop);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_NE(output.status.reason.find("planner reports no path to goal 5"), std::string::npos)
      << output.status.reason;

  // The next plan with a path gets the vehicle going again.
  path_ = pushing;
  path_.sequence = 3;
  path_.utime = now_us_ + kCycleUs;
  path_.push_plans.clear();
  path_.waypoints = {waypoint(pose_.x, WaypointKind::Free), waypoint(6.0, WaypointKind::Free)};
  output = cycle({});
  EXPECT_EQ(output.status.mode, Mode::Follow);
}

TEST_F(ExecutivePushObstaclesTest, AfterAnUnpushableObjectTheVehicleBacksAwayBeforeFollowing)
{
  Output output;
  for (int index = 0; index < 500 && output.status.mode != Mode::Push; ++index) {
    output = cycle({});
  }
  ASSERT_EQ(output.status.mode, Mode::Push);
  const double stall_force = 0.95 * vehicle_.maxPushForce();
  for (int index = 0; index < 500 && output.status.mode != Mode::ReplanWait; ++index) {
    output = cycle({}, stall_force);
  }
  ASSERT_EQ(output.status.mode, Mode::ReplanWait);
  const Point stalled = pose_.position();

  // The replanned path goes around: straight ahead is the box on the bumper, so the follower alone
  // would be boxed in. The vehicle reverses release_m first.
  path_.sequence = 2;
  path_.utime = now_us_ + kCycleUs;
  path_.push_plans.clear();
  path_.waypoints = {waypoint(stalled.x(), WaypointKind::Free), waypoint(6.0, WaypointKind::Free)};
  path_.waypoints[1].position = Point(stalled.x(), 2.0);
  output = cycle({}, 0.0);
  EXPECT_EQ(output.status.mode, Mode::Follow);
  EXPECT_LT(output.command.linear, 0.0);
  EXPECT_NE(output.status.reason.find("backing away from object 9"), std::string::npos)
      << output.status.reason;
  for (int index = 0; index < 200 && output.command.linear <= 0.0; ++index) {
    output = cycle({}, 0.0);
  }
  EXPECT_NEAR((pose_.position() - stalled).norm(), settings_.pusher.release_m, 0.02);
  EXPECT_NE(output.status.reason.find("waypoint"), std::string::npos) << output.status.reason;
}

TEST_F(ExecutivePushObstaclesTest, WedgedAtASlantTheVehicleBacksAwayOnAnArc)
{
  Output output = pushUntilTheObjectStalls();
  ASSERT_EQ(output.status.mode, Mode::ReplanWait);
  const Pose2 stalled = pose_;
  // A wall behind the left side at a slant: 0.06 m off the rear-left corner, closing in on it by 0.5 m
  // per metre the vehicle goes straight back (the Willow passage after a push that turned the vehicle).
  const Footprint footprint = vehicleFootprint(vehicle_, settings_.reference_to_bumper_m);
  std::vector<Point> wall;
  for (int step = -20; step <= 40; ++step) {
    const double back = step * 0.025;  // metres behind the rear face
    wall.push_back(
        stalled.transform(Point(-footprint.rear_m - back, footprint.half_width_m + 0.06 - 0.5 * back)));
  }
  replanLeftOf(stalled.position());

  // Straight back is refused by the guard (it would bring the corner within its clearance of the wall):
  output = cycle(wall, 0.0);
  EXPECT_EQ(output.status.mode, Mode::Follow);
  EXPECT_LT(output.command.linear, 0.0);
  EXPECT_GT(output.command.angular, 0.0) << output.status.reason;  // the rear swings right, off the wall
  EXPECT_NE(output.status.reason.find("backing away from object 9"), std::string::npos)
      << output.status.reason;
  EXPECT_NE(output.status.reason.find("on an arc turning left"), std::string::npos) << output.status.reason;
  double closest = 1.0;
  for (int index = 0; index < 200 && output.command.linear <= 0.0; ++index) {
    output = cycle(wall, 0.0);
    for (const Point& point : wall) {
      closest = std::min(closest, footprint.distance(pose_, point));
    }
  }
  EXPECT_GE((pose_.position() - stalled.position()).norm(), settings_.pusher.release_m - 0.02);
  EXPECT_GT(closest, 0.04);
  EXPECT_EQ(output.status.reason.find("backing away"), std::string::npos) << output.status.reason;
}

TEST_F(ExecutivePushObstaclesTest, HemmedInBehindTheVehicleFollowsTheNewPathAtOnce)
{
  Output output = pushUntilTheObjectStalls();
  ASSERT_EQ(output.status.mode, Mode::ReplanWait);
  const Pose2 stalled = pose_;
  // A wall square across the rear, 0.06 m behind it: no reverse arc keeps out of the guard's clearance.
  const Footprint footprint = vehicleFootprint(vehicle_, settings_.reference_to_bumper_m);
  std::vector<Point> wall;
  for (int step = -30; step <= 30; ++step) {
    wall.push_back(stalled.transform(Point(-footprint.rear_m - 0.06, step * 0.025)));
  }
  replanLeftOf(stalled.position());
  output = cycle(wall, 0.0);
  EXPECT_EQ(output.command.linear, 0.0);
  EXPECT_NE(output.status.reason.find("stopped: obstacle"), std::string::npos) << output.status.reason;
  // It does not wait there for ever (it did, until the run timed out): the next cycle follows.
  output = cycle(wall, 0.0);
  EXPECT_EQ(output.status.mode, Mode::Follow);
  EXPECT_EQ(output.status.reason.find("backing away"), std::string::npos) << output.status.reason;
}

TEST_F(ExecutivePushObstaclesTest, ApproachEstimateIsTheObjectAtFirstContact)
{
  const Output output = cycle({});
  ASSERT_EQ(output.status.mode, Mode::Approach) << output.status.reason;
  const std::optional<ObjectObservation> expected = executive_.pushedObjectEstimate();
  ASSERT_TRUE(expected.has_value());
  EXPECT_NEAR(expected->position.x(), kObjectStart.x(), 1e-9);
  EXPECT_NEAR(expected->position.y(), kObjectStart.y(), 1e-9);
}

TEST_F(ExecutivePushObstaclesTest, SomethingElseBesideTheCreepStopsIt)
{
  // A post 2 cm beside the lane, ahead of the bumper and beyond the object's radius: creeping on would
  // scrape it.
  const std::vector<Point> post = {Point(1.5, vehicle_.width_m / 2.0 + 0.02)};
  ASSERT_GT((post[0] - kObjectStart).norm(), settings_.pushed_object.radius_m);
  Output output;
  for (int index = 0; index < 125; ++index) {  // 2.5 s: stopped, not yet given up
    output = cycle(post);
  }
  EXPECT_EQ(output.status.mode, Mode::Approach);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_NE(output.status.reason.find("stopped: obstacle"), std::string::npos) << output.status.reason;
  // Stopped with the bumper short of the post (the guard keeps 5 cm).
  EXPECT_LT(pose_.x + settings_.reference_to_bumper_m, 1.5);
  EXPECT_GT(pose_.x, 0.9);  // it did creep until the post came close
}

TEST_F(ExecutivePushObstaclesTest, ObjectIsAnObstacleWhileFollowing)
{
  // Far from the topological waypoint the executive follows; the box right ahead blocks the straight arc.
  pose_ = {-3.0, 0.0, 0.0};
  object_ = Point(-1.9, 0.0);
  const Output output = cycle({});
  EXPECT_EQ(output.status.mode, Mode::Follow);
  EXPECT_FALSE(executive_.pushedObjectEstimate().has_value());
  EXPECT_EQ(output.status.reason.find("no fresh obstacle points"), std::string::npos);
}

}  // namespace
}  // namespace ifar::executive
