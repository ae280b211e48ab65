#include "lcmtypes/samples/sample_messages.hpp"

#include <algorithm>

#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/can_bus_status_t.hpp"
#include "ifar/can_frame_t.hpp"
#include "ifar/dv_graph_t.hpp"
#include "ifar/e_stop_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/force_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/heartbeat_t.hpp"
#include "ifar/motor_status_t.hpp"
#include "ifar/node_journal_t.hpp"
#include "ifar/object_polygons_t.hpp"
#include "ifar/odometry_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "ifar/velodyne_status_t.hpp"
#include "ifar/world_state_t.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace ifar::lcmtypes_samples {
namespace {

constexpr std::int64_t kUtime = 1'763'800'000'123'456;

polygon_t samplePolygon(std::int64_t id, std::int8_t kind, int points)
{
  polygon_t polygon;
  polygon.id = id;
  polygon.kind = kind;
  polygon.num_points = points;
  for (int index = 0; index < points; ++index) {
    polygon.x.push_back(1.25 * index + 0.5 * static_cast<double>(id));
    polygon.y.push_back(-0.75 * index + 2.0);
  }
  return polygon;
}

push_control_t sampleControl(std::int8_t kind, int index)
{
  push_control_t control;
  control.kind = kind;
  control.contact_edge = index % 4;
  control.linear_velocity = 0.3 + 0.01 * index;
  control.angular_velocity = -0.05 * index;
  control.duration_s = 1.5;
  control.vehicle_x = 3.0 + index;
  control.vehicle_y = 4.0 - index;
  control.vehicle_heading = 0.25 * index;
  control.object_x = 3.8 + index;
  control.object_y = 4.1 - index;
  control.object_heading = -0.1 * index;
  return control;
}

push_plan_t samplePushPlan()
{
  push_plan_t plan;
  plan.utime = kUtime + 7;
  plan.object_id = 42;
  plan.from_vertex = 1001;
  plan.to_vertex = 1002;
  plan.contact_edge = 2;
  plan.contact_x = 5.5;
  plan.contact_y = -1.5;
  plan.contact_heading = 1.5707963267948966;
  plan.controls = {sampleControl(push_control_t::KIND_PUSH, 0),
                   sampleControl(push_control_t::KIND_SWITCH_CONTACT, 1),
                   sampleControl(push_control_t::KIND_PUSH, 2)};
  plan.num_controls = static_cast<std::int32_t>(plan.controls.size());
  plan.expected_force_n = 137.5;
  plan.push_distance_m = 1.8;
  plan.travel_m = 3.25;
  plan.expected_cost = 7.5;
  plan.affordance = 0.45;
  return plan;
}

affordance_t makeAffordance()
{
  affordance_t message;
  message.utime = kUtime;
  message.object_id = 42;
  message.pushable = true;
  message.push_force_n = 212.5;
  message.affordance = 0.61;
  message.planned_cost = 7.5;
  message.measured_cost = 11.25;
  message.reason = affordance_t::REASON_COST_HIGHER;
  return message;
}

blocked_passage_t makeBlockedPassage()
{
  blocked_passage_t message;
  message.utime = kUtime;
  message.goal_id = 7;
  message.from_x = 20.75;
  message.from_y = 27.67;
  message.to_x = 19.73;
  message.to_y = 27.97;
  message.stalls = 3;
  message.reason = "stalled 3 times within 1.0 m of (20.75, 27.67) toward (19.73, 27.97)";
  return message;
}

can_bus_status_t makeCanBusStatus()
{
  can_bus_status_t message;
  message.utime = kUtime;
  message.bus_name = "vcan0";
  message.state = can_bus_status_t::STATE_PASSIVE;
  message.frames_received = 123456;
  message.frames_sent = 65432;
  message.error_frames = 17;
  message.write_errors = 3;
  message.bad_frames = 9;
  return message;
}

can_frame_t makeCanFrame()
{
  can_frame_t message;
  message.utime = kUtime;
  message.id = 0x201;
  message.flags = can_frame_t::FLAG_EXTENDED;
  message.dlc = 6;
  const std::uint8_t bytes[8] = {0x0F, 0x00, 0xE8, 0x03, 0x00, 0x00, 0x00, 0x00};
  std::copy(bytes, bytes + 8, message.data);
  return message;
}

dv_graph_t makeDvGraph()
{
  dv_graph_t message;
  message.utime = kUtime;
  message.sequence = 77;
  message.polygons = {samplePolygon(1, polygon_t::KIND_BACKGROUND, 4),
                      samplePolygon(2, polygon_t::KIND_MOVABLE, 5)};
  message.num_polygons = 2;
  for (int index = 0; index < 3; ++index) {
    graph_vertex_t vertex;
    vertex.id = 100 + index;
    vertex.kind = static_cast<std::int8_t>(index);
    vertex.x = 0.5 * index;
    vertex.y = -0.5 * index;
    vertex.polygon_id = index == 0 ? 1 : -1;
    message.vertices.push_back(vertex);
  }
  message.num_vertices = 3;
  graph_edge_t visibility;
  visibility.from_id = 100;
  visibility.to_id = 101;
  visibility.kind = graph_edge_t::KIND_VISIBILITY;
  visibility.cost = 0.7071067811865476;
  visibility.object_id = -1;
  graph_edge_t interaction = visibility;
  interaction.to_id = 102;
  interaction.kind = graph_edge_t::KIND_INTERACTION;
  interaction.cost = 9.5;
  interaction.object_id = 2;
  message.edges = {visibility, interaction};
  message.num_edges = 2;
  return message;
}

e_stop_t makeEStop()
{
  e_stop_t message;
  message.utime = kUtime;
  message.engaged = true;
  message.source = "operator";
  message.reason = "person in the work area";
  return message;
}

exec_status_t makeExecStatus()
{
  exec_status_t message;
  message.utime = kUtime;
  message.mode = exec_status_t::MODE_PUSH;
  message.goal_id = 5;
  message.waypoint_index = 3;
  message.target_x = 12.5;
  message.target_y = -3.25;
  message.target_object_id = 42;
  message.stale = exec_status_t::STALE_FORCE;
  message.pushes = 1;
  message.replans = 2;
  message.reason = "pushing object 42 along plan 0";
  return message;
}

force_t makeForce()
{
  force_t message;
  message.utime = kUtime;
  message.force_n = 312.5F;
  message.counter = 201;
  message.status = force_t::STATUS_OVERLOAD;
  message.frames_bad = 4;
  return message;
}

goal_t makeGoal()
{
  goal_t message;
  message.utime = kUtime;
  message.goal_id = 5;
  message.x = 14.75;
  message.y = 9.5;
  message.cancel = false;
  return message;
}

heartbeat_t makeHeartbeat()
{
  heartbeat_t message;
  message.utime = kUtime;
  message.process = "planner";
  message.pid = 4242;
  message.sequence = 99;
  message.health = heartbeat_t::HEALTH_DEGRADED;
  message.message = "packets late";
  return message;
}

node_journal_t makeNodeJournal()
{
  node_journal_t message;
  message.utime = kUtime;
  message.node = "planner";
  message.start_utime = kUtime - 2'500'000;
  message.pid = 4243;
  message.first_event = 17;
  message.channels = {"POSE", "VELODYNE_PACKET"};
  message.num_channels = 2;
  message.kinds = {node_journal_t::KIND_INPUT, node_journal_t::KIND_TIMER, node_journal_t::KIND_JOB_FINISHED};
  message.codes = {1, 0, 0};
  message.utimes = {kUtime - 30'000, kUtime - 20'000, kUtime - 10'000};
  message.hashes = {-123'456'789, 0, 0};
  message.num_events = 3;
  return message;
}

motor_status_t makeMotorStatus()
{
  motor_status_t message;
  message.utime = kUtime;
  message.node_id = 2;
  message.nmt_state = 0x05;
  message.heartbeat_ok = true;
  message.statusword = 0x0627;
  message.drive_state = motor_status_t::DRIVE_OPERATION_ENABLED;
  message.target_velocity = 5000;
  message.actual_velocity = 4987;
  message.emergency_code = 0x2310;
  message.reason = "";
  return message;
}

object_polygons_t makeObjectPolygons()
{
  object_polygons_t message;
  message.utime = kUtime;
  message.polygons = {samplePolygon(7, polygon_t::KIND_MOVABLE, 4)};
  message.num_polygons = 1;
  return message;
}

odometry_t makeOdometry()
{
  odometry_t message;
  message.utime = kUtime;
  message.left_node_id = 1;
  message.right_node_id = 2;
  message.left_wheel_rad_s = 1.5;
  message.right_wheel_rad_s = 2.25;
  message.linear_velocity = 0.28125;
  message.angular_velocity = 0.1875;
  message.left_age_us = 4000;
  message.right_age_us = 61000;
  message.status = odometry_t::STATUS_RIGHT_STALE;
  return message;
}

path_t makePath()
{
  path_t message;
  message.utime = kUtime;
  message.goal_id = 5;
  message.sequence = 12;
  message.valid = true;
  message.length_m = 18.5;
  message.cost = 23.25;
  for (int index = 0; index < 3; ++index) {
    waypoint_t waypoint;
    waypoint.x = 1.0 + index;
    waypoint.y = 2.0 * index;
    waypoint.kind = static_cast<std::int8_t>(index);
    waypoint.object_id = index == 2 ? 42 : -1;
    waypoint.push_plan_index = index == 2 ? 0 : -1;
    message.waypoints.push_back(waypoint);
  }
  message.num_waypoints = 3;
  message.push_plans = {samplePushPlan()};
  message.num_push_plans = 1;
  return message;
}

planner_status_t makePlannerStatus()
{
  planner_status_t message;
  message.utime = kUtime;
  message.state = planner_status_t::STATE_PLANNING;
  message.flags = planner_status_t::FLAG_GOAL_SNAPPED | planner_status_t::FLAG_BAD_POINTS;
  message.frames = 1234;
  message.perception_ms = 7.5F;
  message.local_graph_ms = 1.25F;
  message.merge_ms = 0.5F;
  message.interaction_ms = 3.75F;
  message.search_ms = 0.125F;
  message.total_ms = 13.125F;
  message.num_points = 28800;
  message.num_polygons = 37;
  message.num_vertices = 412;
  message.num_edges = 2210;
  message.num_interaction_edges = 6;
  message.bad_inputs = 3;
  message.message = "goal moved 0.4 m out of an obstacle";
  return message;
}

pose_t makePose()
{
  pose_t message;
  message.utime = kUtime;
  const double position[3] = {10.5, -4.25, 0.125};
  const double orientation[4] = {0.9238795325112867, 0.0, 0.0, 0.3826834323650898};
  const double velocity[3] = {0.5, 0.25, 0.0};
  const double angular[3] = {0.0, 0.0, 0.3};
  std::copy(position, position + 3, message.position);
  std::copy(orientation, orientation + 4, message.orientation);
  std::copy(velocity, velocity + 3, message.velocity);
  std::copy(angular, angular + 3, message.angular_velocity);
  return message;
}

velocity_cmd_t makeVelocityCommand()
{
  velocity_cmd_t message;
  message.utime = kUtime;
  message.linear_velocity = 0.75;
  message.angular_velocity = -0.3;
  message.left_wheel = 5.6;
  message.right_wheel = 4.4;
  return message;
}

velodyne_packet_t makeVelodynePacket()
{
  velodyne_packet_t message;
  message.utime = kUtime;
  message.device_time_past_hour = 1'234'567'890;
  message.port = 2368;
  message.size = 1206;
  message.data.resize(1206);
  for (std::size_t index = 0; index < message.data.size(); ++index) {
    message.data[index] = static_cast<std::uint8_t>((index * 31 + 7) & 0xFF);
  }
  return message;
}

velodyne_status_t makeVelodyneStatus()
{
  velodyne_status_t message;
  message.utime = kUtime;
  message.packets_per_second = 753.5F;
  message.packets_received = 90000;
  message.packets_published = 89990;
  message.bad_packets = 10;
  message.dropped_packets = 2;
  message.last_error = "wrong block marker 0x1234 in block 3";
  return message;
}

world_state_t makeWorldState()
{
  world_state_t message;
  message.utime = kUtime;
  message.vehicle_x = 3.5;
  message.vehicle_y = 1.25;
  message.vehicle_heading = 0.785;
  message.bumper_force_n = 180.0;
  for (int index = 0; index < 2; ++index) {
    object_state_t object;
    object.id = 40 + index;
    object.x = 5.0 + index;
    object.y = 2.0 - index;
    object.heading = 0.1 * index;
    object.linear_velocity[0] = 0.2;
    object.linear_velocity[1] = -0.1 * index;
    object.angular_velocity = 0.05;
    object.movable = true;
    message.objects.push_back(object);
  }
  message.num_objects = 2;
  return message;
}

template <typename Message>
SampleMessage sample(const std::string& channel, const Message& message)
{
  SampleMessage result;
  result.type_name = Message::getTypeName();
  result.channel = channel;
  result.fingerprint = Message::getHash();
  result.encoded.resize(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(result.encoded.data(), 0, static_cast<int>(result.encoded.size()));
  result.reencode = [](common::ByteView bytes, std::vector<std::uint8_t>& reencoded) {
    Message decoded;
    if (lcmtypes::decodeLcm(decoded, bytes.data(), bytes.size()).bytes != static_cast<int>(bytes.size())) {
      return false;
    }
    reencoded.resize(static_cast<std::size_t>(decoded.getEncodedSize()));
    decoded.encode(reencoded.data(), 0, static_cast<int>(reencoded.size()));
    return true;
  };
  return result;
}

}  // namespace

std::vector<SampleMessage> allSampleMessages()
{
  // Nested-only types (polygon_t, graph_vertex_t, graph_edge_t, waypoint_t, push_control_t,
  // object_state_t) travel inside these and also get a sample of their own for the fingerprint check.
  polygon_t polygon = samplePolygon(3, polygon_t::KIND_BACKGROUND, 3);
  graph_vertex_t vertex = makeDvGraph().vertices.front();
  graph_edge_t edge = makeDvGraph().edges.back();
  waypoint_t waypoint = makePath().waypoints.back();
  push_control_t control = sampleControl(push_control_t::KIND_PUSH, 1);
  object_state_t object = makeWorldState().objects.front();
  return {
      sample("AFFORDANCE", makeAffordance()),
      sample("BLOCKED_PASSAGE", makeBlockedPassage()),
      sample("CAN_STATUS", makeCanBusStatus()),
      sample("CAN_VEHICLE", makeCanFrame()),
      sample("DV_GRAPH", makeDvGraph()),
      sample("E_STOP", makeEStop()),
      sample("EXEC_STATUS", makeExecStatus()),
      sample("FORCE", makeForce()),
      sample("GOAL", makeGoal()),
      sample("TEST_GRAPH_EDGE", edge),
      sample("TEST_GRAPH_VERTEX", vertex),
      sample("HEARTBEAT", makeHeartbeat()),
      sample("MOTOR_STATUS", makeMotorStatus()),
      sample("PLANNER_JOURNAL", makeNodeJournal()),
      sample("DETECTED_OBJECTS", makeObjectPolygons()),
      sample("TEST_OBJECT_STATE", object),
      sample("ODOMETRY", makeOdometry()),
      sample("GLOBAL_PATH", makePath()),
      sample("PLANNER_STATUS", makePlannerStatus()),
      sample("TEST_POLYGON", polygon),
      sample("POSE", makePose()),
      sample("TEST_PUSH_CONTROL", control),
      sample("PUSH_PLAN", samplePushPlan()),
      sample("VELOCITY_CMD", makeVelocityCommand()),
      sample("VELODYNE_PACKET", makeVelodynePacket()),
      sample("VELODYNE_STATUS", makeVelodyneStatus()),
      sample("TEST_WAYPOINT", waypoint),
      sample("SIM_GROUND_TRUTH", makeWorldState()),
  };
}

}  // namespace ifar::lcmtypes_samples
