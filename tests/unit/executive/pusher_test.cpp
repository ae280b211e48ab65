#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "executive/follower/arc.hpp"
#include "executive/pusher/approach.hpp"
#include "executive/pusher/push_tracker.hpp"
#include "tests/unit/executive/simulation.hpp"

namespace ifar::executive {
namespace {

using geometry::Pose2;

PushControl pushFor(const Pose2& start, double linear, double angular, double duration)
{
  PushControl control;
  control.kind = PushControlKind::Push;
  control.linear_velocity = linear;
  control.angular_velocity = angular;
  control.duration_s = duration;
  control.expected_vehicle_pose = integrateArc(start, linear, angular, duration);
  return control;
}

class PusherTest : public ::testing::Test {
 protected:
  common::VehicleSettings vehicle_;
  DifferentialDrive drive_{vehicle_};
  FollowerSettings follower_;
  ApproachSettings approach_;
  PushTrackerSettings tracker_settings_;

  /// What an approach driven to its end (at most 100 s) went through.
  struct ApproachRun {
    Pose2 end;
    bool crept = false;
    bool turned_on_the_spot_or_followed = false;  ///< a step in ToStandoff or Align
    bool done = false;
  };
  ApproachRun driveApproach(Approach& approach, Pose2 pose) const
  {
    ApproachRun run;
    for (int step = 0; step < 5000; ++step) {
      const ApproachStep result = approach.step(pose, 0.0, {}, approach_, follower_, drive_);
      if (result.phase == ApproachPhase::Done) {
        run.done = true;
        break;
      }
      run.crept = run.crept || result.phase == ApproachPhase::Creep;
      run.turned_on_the_spot_or_followed =
          run.turned_on_the_spot_or_followed || result.phase != ApproachPhase::Creep;
      pose = testing::drive(pose, drive_.limitSpeed(result.command), 0.02);
    }
    run.end = pose;
    return run;
  }
};

TEST(ProjectOntoArc, StraightArcAndSpin)
{
  const Pose2 start{1.0, 1.0, 0.0};
  EXPECT_NEAR(projectOntoArc(start, 0.5, 0.0, 0.0, {2.0, 1.3, 0.0}), 2.0, 1e-12);
  // Quarter circle of radius 1 left: after pi/2 s at (0, 1) rad/s... position angle advances with time.
  const Pose2 origin{0.0, 0.0, 0.0};
  const Pose2 quarter = integrateArc(origin, 1.0, 1.0, 1.2);
  EXPECT_NEAR(projectOntoArc(origin, 1.0, 1.0, 1.0, quarter), 1.2, 1e-9);
  const Pose2 more_than_half = integrateArc(origin, 1.0, 1.0, 4.0);  // past pi: needs the search hint
  EXPECT_NEAR(projectOntoArc(origin, 1.0, 1.0, 3.8, more_than_half), 4.0, 1e-9);
  EXPECT_NEAR(projectOntoArc(origin, 0.0, 0.5, 0.0, {0.0, 0.0, 0.4}), 0.8, 1e-9);
}

TEST_F(PusherTest, TracksStraightPushFromOffsetStart)
{
  PushPlan plan;
  plan.object_id = 7;
  plan.contact_pose = {0.0, 0.0, 0.0};
  plan.controls.push_back(pushFor(plan.contact_pose, 0.3, 0.0, 6.0));  // 1.8 m along +x

  PushTracker tracker;
  tracker.begin(plan);
  Pose2 pose{0.0, 0.08, 0.1};  // 8 cm left of the lane, turned 0.1 rad
  Pose2 end_of_push = pose;
  double worst_late_cross_track = 0.0;
  bool pushing_done = false;
  int step = 0;
  for (; step < 2000 && !tracker.finished(); ++step) {
    const PushStep result = tracker.step(pose, 100.0, {}, tracker_settings_, approach_, follower_, drive_);
    if (result.phase == PushPhase::Pushing) {
      EXPECT_TRUE(result.expects_contact);
      if (pose.x > 1.2) {  // converged within the first 1.2 m
        worst_late_cross_track = std::max(worst_late_cross_track, std::abs(pose.y));
      }
      end_of_push = pose;
    } else if (result.phase == PushPhase::Releasing) {
      pushing_done = true;
      EXPECT_LT(result.command.linear, 0.0);
    }
    pose = testing::drive(pose, drive_.limitSpeed(result.command), 0.02);
  }
  EXPECT_TRUE(tracker.finished());
  EXPECT_TRUE(pushing_done);
  EXPECT_LT(worst_late_cross_track, 0.02);
  EXPECT_NEAR(end_of_push.x, 1.8, 0.05);
  EXPECT_NEAR(end_of_push.y, 0.0, 0.02);
  EXPECT_NEAR(end_of_push.heading, 0.0, 0.03);
  EXPECT_NEAR(pose.x, 1.8 - tracker_settings_.release_m, 0.05);  // backed away from the object
}

TEST_F(PusherTest, TracksCurvedPush)
{
  PushPlan plan;
  plan.contact_pose = {1.0, 2.0, 0.5};
  plan.controls.push_back(pushFor(plan.contact_pose, 0.3, 0.15, 5.0));
  const Pose2 expected = plan.controls.back().expected_vehicle_pose;

  PushTracker tracker;
  tracker.begin(plan);
  Pose2 pose = plan.contact_pose;
  Pose2 end_of_push = pose;
  for (int step = 0; step < 2000 && !tracker.finished(); ++step) {
    const PushStep result = tracker.step(pose, 100.0, {}, tracker_settings_, approach_, follower_, drive_);
    if (result.phase == PushPhase::Pushing) {
      end_of_push = pose;
    }
    pose = testing::drive(pose, drive_.limitSpeed(result.command), 0.02);
  }
  ASSERT_TRUE(tracker.finished());
  EXPECT_NEAR(end_of_push.x, expected.x, 0.03);
  EXPECT_NEAR(end_of_push.y, expected.y, 0.03);
  EXPECT_NEAR(end_of_push.heading, expected.heading, 0.03);
}

TEST_F(PusherTest, SwitchesContactBetweenPushes)
{
  PushPlan plan;
  plan.contact_pose = {0.0, 0.0, 0.0};
  plan.controls.push_back(pushFor(plan.contact_pose, 0.3, 0.0, 2.0));  // to (0.6, 0)
  PushControl switch_contact;
  switch_contact.kind = PushControlKind::SwitchContact;
  switch_contact.contact_edge = 1;
  switch_contact.expected_vehicle_pose = {1.2, -1.0, 1.5707963267948966};  // push from below, along +y
  plan.controls.push_back(switch_contact);
  plan.controls.push_back(pushFor(switch_contact.expected_vehicle_pose, 0.3, 0.0, 2.0));  // to (1.2, -0.4)

  PushTracker tracker;
  tracker.begin(plan);
  Pose2 pose = plan.contact_pose;
  bool backed_off = false;
  bool switched = false;
  Pose2 end_of_push = pose;
  for (int step = 0; step < 5000 && !tracker.finished(); ++step) {
    const PushStep result = tracker.step(pose, 0.0, {}, tracker_settings_, approach_, follower_, drive_);
    backed_off = backed_off || result.phase == PushPhase::BackingOff;
    switched = switched || result.phase == PushPhase::Switching;
    if (result.phase == PushPhase::Pushing && result.control_index == 2) {
      end_of_push = pose;
    }
    pose = testing::drive(pose, drive_.limitSpeed(result.command), 0.02);
  }
  ASSERT_TRUE(tracker.finished());
  EXPECT_TRUE(backed_off);
  EXPECT_TRUE(switched);
  EXPECT_NEAR(end_of_push.x, 1.2, 0.05);
  EXPECT_NEAR(end_of_push.y, -0.4, 0.05);
}

TEST_F(PusherTest, ApproachReachesContactPose)
{
  const Pose2 contact{2.0, 1.0, 0.3};
  Approach approach;
  Pose2 pose{-2.0, -1.0, 2.0};
  approach.begin(contact, pose, approach_);
  EXPECT_EQ(approach.phase(), ApproachPhase::ToStandoff);
  const ApproachRun run = driveApproach(approach, pose);
  EXPECT_TRUE(run.crept);
  EXPECT_TRUE(run.done);
  EXPECT_NEAR(run.end.x, contact.x, 0.06);
  EXPECT_NEAR(run.end.y, contact.y, 0.06);
  EXPECT_NEAR(run.end.heading, contact.heading, 0.06);
}

TEST_F(PusherTest, ApproachEndsOnContactForce)
{
  const Pose2 contact{1.0, 0.0, 0.0};
  Approach approach;
  const Pose2 pose{0.8, 0.0, 0.0};  // in the lane, 0.2 m short: within force_contact_reach_m
  approach.begin(contact, pose, approach_);
  EXPECT_EQ(approach.phase(), ApproachPhase::Align);
  const ApproachStep creeping = approach.step(pose, 0.0, {}, approach_, follower_, drive_);
  EXPECT_EQ(creeping.phase, ApproachPhase::Creep);
  EXPECT_GT(creeping.command.linear, 0.0);
  const ApproachStep touching = approach.step(pose, 50.0, {}, approach_, follower_, drive_);
  EXPECT_EQ(touching.phase, ApproachPhase::Done);
  EXPECT_TRUE(touching.command.isZero());
}

TEST_F(PusherTest, ForceFeltFartherFromTheContactThanItsReachIsNotTheObject)
{
  // 0.5 m short of the contact, more than force_contact_reach_m (0.3): the bumper presses on something
  // the lidar does not show. The creep goes on (standing still there gives the contact up as not reached).
  ASSERT_DOUBLE_EQ(approach_.force_contact_reach_m, 0.3);
  const Pose2 contact{1.0, 0.0, 0.0};
  Approach approach;
  const Pose2 pose{0.5, 0.0, 0.0};
  approach.begin(contact, pose, approach_);
  const ApproachStep pressing = approach.step(pose, 200.0, {}, approach_, follower_, drive_);
  EXPECT_EQ(pressing.phase, ApproachPhase::Creep);
  EXPECT_GT(pressing.command.linear, 0.0);
  const ApproachStep closer = approach.step(Pose2{0.75, 0.0, 0.0}, 200.0, {}, approach_, follower_, drive_);
  EXPECT_EQ(closer.phase, ApproachPhase::Done);
}

TEST_F(PusherTest, AStuckApproachInThePushLaneJoinsItAndCreepsToTheContact)
{
  const Pose2 contact{1.0, 0.0, 0.0};
  // In the lane 1.0 m behind the contact (further back than the stand-off point), 0.15 m beside its line
  // and 0.3 rad off its heading.
  const Pose2 in_lane{0.0, 0.15, -0.3};
  Approach approach;
  approach.begin(contact, in_lane, approach_);
  ASSERT_EQ(approach.phase(), ApproachPhase::ToStandoff);
  for (const Pose2& outside :
       {Pose2{-0.7, 0.0, 0.0}, Pose2{0.0, 0.25, 0.0}, Pose2{0.0, 0.0, 0.5}, Pose2{1.2, 0.0, 0.0}}) {
    EXPECT_FALSE(approach.joinLane(outside, approach_));
    EXPECT_EQ(approach.phase(), ApproachPhase::ToStandoff);
  }
  ApproachSettings never = approach_;
  never.lane_join_heading_rad = 0.0;
  EXPECT_FALSE(approach.joinLane(in_lane, never));

  ASSERT_TRUE(approach.joinLane(in_lane, approach_));
  EXPECT_FALSE(approach.joinLane(in_lane, approach_));  // only from the collision-free leg
  const ApproachRun run = driveApproach(approach, in_lane);
  EXPECT_TRUE(run.crept);
  EXPECT_FALSE(run.turned_on_the_spot_or_followed);
  EXPECT_TRUE(run.done);
  EXPECT_NEAR(run.end.x, contact.x, 0.06);
  EXPECT_NEAR(run.end.y, contact.y, 0.06);
  EXPECT_NEAR(run.end.heading, contact.heading, 0.06);
}

}  // namespace
}  // namespace ifar::executive
