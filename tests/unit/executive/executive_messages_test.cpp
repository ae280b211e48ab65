#include "executive/node/executive_messages.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace ifar::executive {
namespace {

TEST(LcmConversions, PoseHeadingFromQuaternion)
{
  ifar::pose_t message{};
  message.position[0] = 1.5;
  message.position[1] = -2.0;
  message.orientation[0] = std::cos(0.35);  // 0.7 rad about z
  message.orientation[3] = std::sin(0.35);
  const geometry::Pose2 pose = fromMessage(message);
  EXPECT_DOUBLE_EQ(pose.x, 1.5);
  EXPECT_DOUBLE_EQ(pose.y, -2.0);
  EXPECT_NEAR(pose.heading, 0.7, 1e-12);
}

TEST(LcmConversions, PathWithPushPlanAndUnknownKinds)
{
  ifar::path_t message{};
  message.utime = 123;
  message.goal_id = 4;
  message.sequence = 9;
  message.valid = 1;
  ifar::waypoint_t topological{};
  topological.x = 1.0;
  topological.kind = ifar::waypoint_t::KIND_TOPOLOGICAL;
  topological.object_id = 7;
  topological.push_plan_index = 0;
  ifar::waypoint_t strange = topological;
  strange.kind = 42;
  message.waypoints = {topological, strange};
  message.num_waypoints = 2;
  ifar::push_plan_t plan{};
  plan.object_id = 7;
  plan.contact_x = 2.0;
  plan.contact_heading = 0.5;
  plan.expected_cost = 3.5;
  ifar::push_control_t push{};
  push.kind = ifar::push_control_t::KIND_PUSH;
  push.linear_velocity = 0.3;
  push.duration_s = 2.0;
  push.vehicle_x = 2.6;
  ifar::push_control_t odd = push;
  odd.kind = 9;
  plan.controls = {push, odd};
  plan.num_controls = 2;
  message.push_plans = {plan};
  message.num_push_plans = 1;

  int malformed = 0;
  const Path path = fromMessage(message, malformed);
  EXPECT_EQ(malformed, 2);
  EXPECT_TRUE(path.valid);
  EXPECT_EQ(path.goal_id, 4);
  EXPECT_EQ(path.sequence, 9);
  ASSERT_EQ(path.waypoints.size(), 2u);
  EXPECT_EQ(path.waypoints[0].kind, WaypointKind::Topological);
  EXPECT_EQ(path.waypoints[1].kind, WaypointKind::Free);
  ASSERT_EQ(path.push_plans.size(), 1u);
  EXPECT_DOUBLE_EQ(path.push_plans[0].contact_pose.heading, 0.5);
  EXPECT_DOUBLE_EQ(path.push_plans[0].expected_cost, 3.5);
  ASSERT_EQ(path.push_plans[0].controls.size(), 1u);
  EXPECT_DOUBLE_EQ(path.push_plans[0].controls[0].expected_vehicle_pose.x, 2.6);
}

TEST(LcmConversions, ForceStatusBits)
{
  ifar::force_t message{};
  message.force_n = 812.0f;
  message.status = ifar::force_t::STATUS_OVERLOAD;
  EXPECT_FALSE(fromMessage(message).faulty);
  EXPECT_DOUBLE_EQ(fromMessage(message).force_n, 812.0);
  message.status = ifar::force_t::STATUS_COUNTER_STUCK;
  EXPECT_TRUE(fromMessage(message).faulty);
}

TEST(LcmConversions, OdometryIsInvalidWhenADriveIsStale)
{
  ifar::odometry_t message{};
  message.linear_velocity = 0.375;
  message.angular_velocity = 0.25;
  OdometryReading reading = fromMessage(message);
  EXPECT_DOUBLE_EQ(reading.linear, 0.375);
  EXPECT_DOUBLE_EQ(reading.angular, 0.25);
  EXPECT_TRUE(reading.valid);
  message.status = ifar::odometry_t::STATUS_RIGHT_STALE;
  EXPECT_FALSE(fromMessage(message).valid);
  message.status = ifar::odometry_t::STATUS_LEFT_STALE;
  EXPECT_FALSE(fromMessage(message).valid);
}

TEST(LcmConversions, MotorNodesCombine)
{
  MotorStatusCombiner motors;
  EXPECT_FALSE(motors.combined().has_value());
  ifar::motor_status_t left{};
  left.node_id = 1;
  left.heartbeat_ok = 1;
  left.drive_state = ifar::motor_status_t::DRIVE_OPERATION_ENABLED;
  ifar::motor_status_t right = left;
  right.node_id = 2;
  motors.update(left, 1000);
  motors.update(right, 2000);
  auto combined = motors.combined();
  ASSERT_TRUE(combined.has_value());
  EXPECT_TRUE(combined->value.heartbeat_ok);
  EXPECT_FALSE(combined->value.fault);
  EXPECT_EQ(combined->utime, 1000);  // the oldest node decides staleness
  right.drive_state = ifar::motor_status_t::DRIVE_FAULT;
  right.reason = "EMCY 0x2310";
  motors.update(right, 3000);
  combined = motors.combined();
  EXPECT_TRUE(combined->value.fault);
  EXPECT_EQ(combined->value.reason, "node 2: EMCY 0x2310");
}

TEST(LcmConversions, OutputMessagesUseTheWireConstants)
{
  Output output;
  output.command = {0.4, -0.2};
  output.wheels = {2.0, 3.0};
  output.status.mode = Mode::ReplanWait;
  output.status.stale = kStaleForce | kStaleMotor;
  output.status.reason = "waiting";
  const ifar::exec_status_t status = toStatusMessage(output, 55);
  EXPECT_EQ(status.mode, ifar::exec_status_t::MODE_REPLAN_WAIT);
  EXPECT_EQ(status.stale, ifar::exec_status_t::STALE_FORCE | ifar::exec_status_t::STALE_MOTOR);
  EXPECT_EQ(status.reason, "waiting");
  EXPECT_EQ(static_cast<int>(Mode::EStop), ifar::exec_status_t::MODE_E_STOP);
  EXPECT_EQ(static_cast<int>(Mode::Arrived), ifar::exec_status_t::MODE_ARRIVED);
  const ifar::velocity_cmd_t command = toVelocityMessage(output, 55);
  EXPECT_DOUBLE_EQ(command.linear_velocity, 0.4);
  EXPECT_DOUBLE_EQ(command.right_wheel, 3.0);

  AffordanceEvent event;
  event.object_id = 3;
  event.pushable = false;
  event.reason = AffordanceReason::NoMotion;
  const ifar::affordance_t affordance = toAffordanceMessage(event, 77);
  EXPECT_EQ(affordance.reason, ifar::affordance_t::REASON_NO_MOTION);
  EXPECT_EQ(affordance.pushable, 0);
  EXPECT_EQ(affordance.object_id, 3);
  event.pushable = true;
  event.reason = AffordanceReason::Jammed;
  const ifar::affordance_t jammed = toAffordanceMessage(event, 78);
  EXPECT_EQ(jammed.reason, ifar::affordance_t::REASON_JAMMED);
  EXPECT_EQ(jammed.pushable, 1);
  event.reason = AffordanceReason::ContactNotReached;
  const ifar::affordance_t not_reached = toAffordanceMessage(event, 79);
  EXPECT_EQ(not_reached.reason, ifar::affordance_t::REASON_CONTACT_NOT_REACHED);
  EXPECT_EQ(not_reached.pushable, 1);

  BlockedPassage passage;
  passage.goal_id = 4;
  passage.from = geometry::Point(20.75, 27.67);
  passage.to = geometry::Point(19.73, 27.97);
  passage.stalls = 3;
  passage.text = "stalled 3 times";
  const ifar::blocked_passage_t blocked = toBlockedPassageMessage(passage, 78);
  EXPECT_EQ(blocked.utime, 78);
  EXPECT_EQ(blocked.goal_id, 4);
  EXPECT_DOUBLE_EQ(blocked.from_x, 20.75);
  EXPECT_DOUBLE_EQ(blocked.from_y, 27.67);
  EXPECT_DOUBLE_EQ(blocked.to_x, 19.73);
  EXPECT_DOUBLE_EQ(blocked.to_y, 27.97);
  EXPECT_EQ(blocked.stalls, 3);
  EXPECT_EQ(blocked.reason, "stalled 3 times");
}

}  // namespace
}  // namespace ifar::executive
