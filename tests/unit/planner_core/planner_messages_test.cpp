// The daemon's LCM conversions: sizes, ids and the polygon orientation convention on a simulated frame.

#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/polygon.hpp"
#include "planner/node/planner_messages.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/world/world_file.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

TEST(PlannerMessages, GraphPathAndStatusCarryThePlannerResult)
{
  FrameAssembler assembler{InputSettings{}};
  const std::vector<FrameInput> frames =
      test_support::feedAll(test_support::recordSimulation(sim::builtinPushRoom(200.0), 0.35), assembler);
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{5, geometry::Point(6.0, 6.0)}));
  const FrameResult result = planner.processFrame(frames.front());
  const PlannerMessages messages = toMessages(planner, result, 123);

  EXPECT_EQ(messages.graph.num_vertices, static_cast<std::int32_t>(planner.graph().vertexCount()));
  EXPECT_EQ(messages.graph.num_edges, static_cast<std::int32_t>(planner.graph().visibilityEdgeCount()));
  EXPECT_EQ(messages.graph.num_polygons, static_cast<std::int32_t>(result.polygons.size()));
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    const polygon_t& polygon = messages.graph.polygons[index];
    geometry::Polygon points;
    for (int vertex = 0; vertex < polygon.num_points; ++vertex) {
      points.emplace_back(polygon.x[static_cast<std::size_t>(vertex)],
                          polygon.y[static_cast<std::size_t>(vertex)]);
    }
    const bool hole = result.polygons[index].boundary == perception::BoundaryKind::Hole;
    EXPECT_EQ(geometry::signedArea(points) < 0.0, hole) << "polygon " << index;
    const bool movable = result.polygons[index].obstacle_class == perception::ObstacleClass::Movable;
    EXPECT_EQ(polygon.kind, movable ? polygon_t::KIND_MOVABLE : polygon_t::KIND_BACKGROUND);
  }

  EXPECT_TRUE(messages.path.valid);
  EXPECT_EQ(messages.path.goal_id, 5);
  EXPECT_EQ(messages.path.utime, 123);
  ASSERT_EQ(messages.path.num_waypoints, static_cast<std::int32_t>(result.path.waypoints.size()));
  EXPECT_EQ(messages.path.waypoints.back().x, 6.0);
  EXPECT_EQ(messages.path.waypoints.front().kind, waypoint_t::KIND_FREE);
  EXPECT_EQ(messages.path.num_push_plans, 0);

  EXPECT_EQ(messages.status.state, planner_status_t::STATE_PLANNING);
  EXPECT_EQ(messages.status.frames, 1);
  EXPECT_EQ(messages.status.num_vertices, messages.graph.num_vertices);
  EXPECT_EQ(messages.status.num_polygons, messages.graph.num_polygons);
}

TEST(PlannerMessages, PushPathCarriesWaypointKindsAndPushPlans)
{
  const sim::WorldResult world =
      sim::loadWorldFile(std::string(IFAR_SOURCE_DIR) + "/config/worlds/demo_room.yaml");
  ASSERT_TRUE(world.ok()) << world.error();
  FrameAssembler assembler{InputSettings{}};
  const std::vector<FrameInput> frames =
      test_support::feedAll(test_support::recordSimulation(world.world(), 0.25), assembler);
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{2, geometry::Point(8.0, 26.0)}));
  const FrameResult result = planner.processFrame(frames.front());
  ASSERT_EQ(result.path.pushes.size(), 1U);
  const PathPush& push = result.path.pushes.front();
  const PlannerMessages messages = toMessages(planner, result, 456);

  // Movable polygons carry the tracked id, background ones ids of their own range.
  bool found_object = false;
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    const polygon_t& polygon = messages.graph.polygons[index];
    if (polygon.kind == polygon_t::KIND_MOVABLE) {
      EXPECT_EQ(polygon.id, result.polygon_ids[index]);
      found_object = found_object || polygon.id == push.object_id;
    } else {
      EXPECT_GE(polygon.id, kBackgroundPolygonIdBase);
    }
  }
  EXPECT_TRUE(found_object);

  ASSERT_EQ(messages.path.num_push_plans, 1);
  ASSERT_EQ(messages.path.num_waypoints, static_cast<std::int32_t>(result.path.waypoints.size()));
  for (std::size_t index = 0; index < messages.path.waypoints.size(); ++index) {
    const waypoint_t& waypoint = messages.path.waypoints[index];
    if (index == push.from_waypoint) {
      EXPECT_EQ(waypoint.kind, waypoint_t::KIND_TOPOLOGICAL);
      EXPECT_EQ(waypoint.push_plan_index, -1);
    } else if (index == push.to_waypoint) {
      EXPECT_EQ(waypoint.kind, waypoint_t::KIND_PUSH);
      EXPECT_EQ(waypoint.object_id, push.object_id);
      EXPECT_EQ(waypoint.push_plan_index, 0);
    } else {
      EXPECT_EQ(waypoint.kind, waypoint_t::KIND_FREE);
      EXPECT_EQ(waypoint.object_id, -1);
    }
  }
  const push_plan_t& plan = messages.path.push_plans.front();
  EXPECT_EQ(plan.utime, 456);
  EXPECT_EQ(plan.object_id, push.object_id);
  EXPECT_EQ(plan.from_vertex, static_cast<std::int64_t>(push.from_vertex));
  EXPECT_EQ(plan.to_vertex, static_cast<std::int64_t>(push.to_vertex));
  EXPECT_EQ(plan.contact_edge, static_cast<std::int32_t>(push.plan.contact_edge));
  EXPECT_DOUBLE_EQ(plan.contact_x, push.plan.contact_pose.x);
  EXPECT_DOUBLE_EQ(plan.contact_y, push.plan.contact_pose.y);
  EXPECT_DOUBLE_EQ(plan.contact_heading, push.plan.contact_pose.heading);
  EXPECT_DOUBLE_EQ(plan.expected_force_n, push.plan.expected_force_n);
  EXPECT_DOUBLE_EQ(plan.push_distance_m, push.plan.push_distance_m);
  EXPECT_DOUBLE_EQ(plan.travel_m, push.plan.travel_distance_m);
  EXPECT_DOUBLE_EQ(plan.expected_cost, push.plan.cost);
  EXPECT_DOUBLE_EQ(plan.affordance, 0.4);
  ASSERT_EQ(plan.num_controls, static_cast<std::int32_t>(push.plan.controls.size()));
  for (std::size_t index = 0; index < plan.controls.size(); ++index) {
    const push_control_t& control = plan.controls[index];
    const interaction::PushControl& planned = push.plan.controls[index];
    EXPECT_EQ(control.kind, planned.kind == interaction::ControlKind::ContactSwitch
                                ? push_control_t::KIND_SWITCH_CONTACT
                                : push_control_t::KIND_PUSH);
    EXPECT_DOUBLE_EQ(control.linear_velocity, planned.linear_mps);
    EXPECT_DOUBLE_EQ(control.angular_velocity, planned.angular_radps);
    EXPECT_DOUBLE_EQ(control.duration_s, planned.duration_s);
    EXPECT_DOUBLE_EQ(control.vehicle_x, planned.vehicle_pose.x);
    EXPECT_DOUBLE_EQ(control.object_y, planned.object_pose.y);
  }
  // The box is pushed north through the doorway.
  EXPECT_GT(plan.controls.back().object_y, 16.5);

  affordance_t affordance{};
  affordance.object_id = push.object_id;
  affordance.pushable = false;
  affordance.push_force_n = 12.5;
  affordance.affordance = 0.25;
  const AffordanceUpdate update = toAffordanceUpdate(affordance);
  EXPECT_EQ(update.object_id, push.object_id);
  EXPECT_FALSE(update.pushable);
  EXPECT_DOUBLE_EQ(update.push_force_n, 12.5);
  EXPECT_DOUBLE_EQ(update.affordance, 0.25);
  EXPECT_FALSE(update.contact_not_reached);
  // A contact not reached is its own outcome: no estimate, and the object stays pushable.
  affordance.pushable = true;
  affordance.reason = affordance_t::REASON_CONTACT_NOT_REACHED;
  const AffordanceUpdate not_reached = toAffordanceUpdate(affordance);
  EXPECT_TRUE(not_reached.contact_not_reached);
  EXPECT_TRUE(not_reached.pushable);

  blocked_passage_t blocked{};
  blocked.from_x = 20.75;
  blocked.from_y = 27.67;
  blocked.to_x = 19.73;
  blocked.to_y = 27.97;
  const BlockedPassage passage = toBlockedPassage(blocked);
  EXPECT_DOUBLE_EQ(passage.from.x(), 20.75);
  EXPECT_DOUBLE_EQ(passage.from.y(), 27.67);
  EXPECT_DOUBLE_EQ(passage.to.x(), 19.73);
  EXPECT_DOUBLE_EQ(passage.to.y(), 27.97);
}

TEST(PlannerMessages, PoseAndDetectorConversionsSkipMalformedData)
{
  pose_t pose{};
  pose.utime = 7;
  pose.position[0] = 1.0;
  pose.orientation[0] = 0.0;
  pose.orientation[3] = 1.0;  // w x y z: half a turn about z
  const PoseSample sample = toPoseSample(pose);
  EXPECT_EQ(sample.utime, 7);
  EXPECT_DOUBLE_EQ(sample.orientation.z(), 1.0);
  EXPECT_DOUBLE_EQ(sample.orientation.w(), 0.0);

  object_polygons_t objects{};
  polygon_t good{};
  good.kind = polygon_t::KIND_MOVABLE;
  good.x = {0.0, 1.0, 1.0};
  good.y = {0.0, 0.0, 1.0};
  good.num_points = 3;
  polygon_t short_arrays = good;
  short_arrays.num_points = 4;  // claims more points than it holds
  polygon_t not_finite = good;
  not_finite.x[1] = std::numeric_limits<double>::quiet_NaN();
  objects.polygons = {good, short_arrays, not_finite};
  objects.num_polygons = 3;
  std::int64_t skipped = 0;
  const std::vector<geometry::Polygon> polygons = toPolygons(objects, skipped);
  ASSERT_EQ(polygons.size(), 1U);
  EXPECT_EQ(skipped, 2);
  EXPECT_EQ(polygons[0][2], geometry::Point(1.0, 1.0));
}

}  // namespace
}  // namespace ifar::planner
