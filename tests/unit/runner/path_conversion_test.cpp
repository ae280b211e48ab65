// The planner's path in the executive's terms: waypoint kinds, object ids, push plan indices and every
// field of a push plan and its controls.

#include "sim/runner/path_conversion.hpp"

#include <gtest/gtest.h>

namespace ifar::runner {
namespace {

graph::PathPoint pathPoint(double x, double y, graph::VertexId vertex = graph::kNoVertex)
{
  graph::PathPoint point;
  point.position = geometry::Point(x, y);
  point.vertex = vertex;
  return point;
}

planner::PathPush examplePush()
{
  planner::PathPush push;
  push.object_id = 7;
  push.from_waypoint = 1;
  push.to_waypoint = 2;
  push.affordance = 0.43;
  interaction::PushPlan& plan = push.plan;
  plan.status = interaction::PlanStatus::Found;
  plan.contact_pose = {1.0, 2.0, 0.5};
  plan.start_object_pose = {1.9, 2.5, 0.1};
  plan.expected_force_n = 77.0;
  plan.push_distance_m = 1.6;
  plan.travel_distance_m = 0.9;
  plan.cost = 2.5;
  interaction::PushControl arc;
  arc.kind = interaction::ControlKind::ArcLeft;
  arc.contact_edge = 2;
  arc.linear_mps = 0.3;
  arc.angular_radps = 0.2;
  arc.duration_s = 1.5;
  arc.vehicle_pose = {1.4, 2.3, 0.8};
  arc.object_pose = {2.1, 2.9, 0.3};
  interaction::PushControl contact_switch;
  contact_switch.kind = interaction::ControlKind::ContactSwitch;
  contact_switch.contact_edge = 3;
  contact_switch.duration_s = 2.0;
  contact_switch.vehicle_pose = {3.0, 1.0, 1.57};
  contact_switch.object_pose = {2.1, 2.9, 0.3};
  plan.controls = {arc, contact_switch};
  return push;
}

TEST(RunnerPathConversion, PushPlanFieldsAndControlKinds)
{
  const executive::PushPlan plan = toExecutivePushPlan(examplePush());
  EXPECT_EQ(plan.object_id, 7);
  EXPECT_DOUBLE_EQ(plan.contact_pose.x, 1.0);
  EXPECT_DOUBLE_EQ(plan.contact_pose.y, 2.0);
  EXPECT_DOUBLE_EQ(plan.contact_pose.heading, 0.5);
  EXPECT_DOUBLE_EQ(plan.expected_force_n, 77.0);
  EXPECT_DOUBLE_EQ(plan.push_distance_m, 1.6);
  EXPECT_DOUBLE_EQ(plan.travel_m, 0.9);
  EXPECT_DOUBLE_EQ(plan.expected_cost, 2.5);
  EXPECT_DOUBLE_EQ(plan.affordance, 0.43);
  ASSERT_EQ(plan.controls.size(), 2U);
  EXPECT_EQ(plan.controls[0].kind, executive::PushControlKind::Push);
  EXPECT_EQ(plan.controls[0].contact_edge, 2);
  EXPECT_DOUBLE_EQ(plan.controls[0].linear_velocity, 0.3);
  EXPECT_DOUBLE_EQ(plan.controls[0].angular_velocity, 0.2);
  EXPECT_DOUBLE_EQ(plan.controls[0].duration_s, 1.5);
  EXPECT_DOUBLE_EQ(plan.controls[0].expected_vehicle_pose.x, 1.4);
  EXPECT_DOUBLE_EQ(plan.controls[0].expected_vehicle_pose.heading, 0.8);
  EXPECT_DOUBLE_EQ(plan.controls[0].expected_object_pose.y, 2.9);
  EXPECT_NEAR(plan.controls[0].expected_object_pose.heading, 0.2, 1e-12);  // turned from 0.1 to 0.3
  EXPECT_EQ(plan.controls[1].kind, executive::PushControlKind::SwitchContact);
  EXPECT_EQ(plan.controls[1].contact_edge, 3);
  EXPECT_DOUBLE_EQ(plan.controls[1].expected_vehicle_pose.heading, 1.57);
}

TEST(RunnerPathConversion, WaypointKindsFromGraphAndPushes)
{
  graph::DvGraph graph;
  graph::Vertex corner;
  corner.kind = graph::VertexKind::Corner;
  corner.position = geometry::Point(5.0, 5.0);
  const graph::VertexId corner_id = graph.addVertex(corner);
  graph::Vertex topological;
  topological.kind = graph::VertexKind::TopologicalWaypoint;
  topological.position = geometry::Point(6.0, 6.0);
  const graph::VertexId topological_id = graph.addVertex(topological);

  planner::PlannedPath path;
  path.valid = true;
  path.goal_id = 3;
  graph::Vertex push_start;
  push_start.kind = graph::VertexKind::TopologicalWaypoint;
  push_start.position = geometry::Point(1.0, 1.0);
  const graph::VertexId push_start_id = graph.addVertex(push_start);

  graph::PathPoint pushed_to = pathPoint(2.0, 3.0);
  pushed_to.interaction = 0;
  pushed_to.object_id = 7;
  path.waypoints = {pathPoint(0.0, 0.0),
                    pathPoint(1.0, 1.0, push_start_id),
                    pushed_to,
                    pathPoint(5.0, 5.0, corner_id),
                    pathPoint(6.0, 6.0, topological_id),
                    pathPoint(9.0, 9.0)};
  path.pushes = {examplePush()};

  const executive::Path out = toExecutivePath(path, graph, 1'000'123, 42);
  EXPECT_EQ(out.utime, 1'000'123);
  EXPECT_EQ(out.sequence, 42);
  EXPECT_EQ(out.goal_id, 3);
  EXPECT_TRUE(out.valid);
  ASSERT_EQ(out.waypoints.size(), 6U);
  ASSERT_EQ(out.push_plans.size(), 1U);
  EXPECT_EQ(out.waypoints[0].kind, executive::WaypointKind::Free);
  EXPECT_EQ(out.waypoints[0].push_plan_index, -1);
  EXPECT_EQ(out.waypoints[1].kind, executive::WaypointKind::Topological);  // where the push starts
  EXPECT_EQ(out.waypoints[1].push_plan_index, -1);  // the executive takes the next waypoint's plan
  EXPECT_EQ(out.waypoints[2].kind, executive::WaypointKind::Push);
  EXPECT_EQ(out.waypoints[2].object_id, 7);
  EXPECT_EQ(out.waypoints[2].push_plan_index, 0);
  EXPECT_DOUBLE_EQ(out.waypoints[2].position.x(), 2.0);
  EXPECT_EQ(out.waypoints[3].kind, executive::WaypointKind::Free);         // a corner
  EXPECT_EQ(out.waypoints[4].kind, executive::WaypointKind::Topological);  // a waypoint passed, no push
  EXPECT_EQ(out.waypoints[4].push_plan_index, -1);
  EXPECT_EQ(out.waypoints[5].kind, executive::WaypointKind::Free);
  EXPECT_EQ(out.push_plans[0].object_id, 7);
}

TEST(RunnerPathConversion, InvalidPathStaysInvalid)
{
  planner::PlannedPath path;
  path.valid = false;
  path.goal_id = 9;
  const executive::Path out = toExecutivePath(path, graph::DvGraph{}, 5, 1);
  EXPECT_FALSE(out.valid);
  EXPECT_EQ(out.goal_id, 9);
  EXPECT_TRUE(out.waypoints.empty());
  EXPECT_TRUE(out.push_plans.empty());
}

TEST(RunnerPathConversion, PushIndicesOutOfRangeAreIgnored)
{
  planner::PlannedPath path;
  path.valid = true;
  graph::PathPoint interaction_without_plan = pathPoint(1.0, 0.0);
  interaction_without_plan.interaction = 3;  // the daemon marks pushes from the plans only
  interaction_without_plan.object_id = 7;
  path.waypoints = {pathPoint(0.0, 0.0), interaction_without_plan};
  planner::PathPush push = examplePush();
  push.from_waypoint = 5;
  push.to_waypoint = 6;
  path.pushes = {push};
  const executive::Path out = toExecutivePath(path, graph::DvGraph{}, 5, 1);
  ASSERT_EQ(out.waypoints.size(), 2U);
  EXPECT_EQ(out.waypoints[0].kind, executive::WaypointKind::Free);
  EXPECT_EQ(out.waypoints[1].kind, executive::WaypointKind::Free);
  EXPECT_EQ(out.waypoints[1].object_id, -1);
  EXPECT_EQ(out.push_plans.size(), 1U);
}

}  // namespace
}  // namespace ifar::runner
