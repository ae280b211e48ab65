#include "executive/node/executive_messages.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ifar::executive {

geometry::Pose2 fromMessage(const ifar::pose_t& message)
{
  const double w = message.orientation[0];
  const double x = message.orientation[1];
  const double y = message.orientation[2];
  const double z = message.orientation[3];
  return {message.position[0], message.position[1],
          std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))};
}

Path fromMessage(const ifar::path_t& message, int& malformed)
{
  Path path;
  path.utime = message.utime;
  path.goal_id = message.goal_id;
  path.sequence = message.sequence;
  path.valid = message.valid != 0;
  path.waypoints.reserve(message.waypoints.size());
  for (const ifar::waypoint_t& source : message.waypoints) {
    Waypoint waypoint;
    waypoint.position = geometry::Point(source.x, source.y);
    waypoint.object_id = source.object_id;
    waypoint.push_plan_index = source.push_plan_index;
    switch (source.kind) {
      case ifar::waypoint_t::KIND_FREE:
        waypoint.kind = WaypointKind::Free;
        break;
      case ifar::waypoint_t::KIND_TOPOLOGICAL:
        waypoint.kind = WaypointKind::Topological;
        break;
      case ifar::waypoint_t::KIND_PUSH:
        waypoint.kind = WaypointKind::Push;
        break;
      default:
        ++malformed;
        break;
    }
    path.waypoints.push_back(waypoint);
  }
  path.push_plans.reserve(message.push_plans.size());
  for (const ifar::push_plan_t& source : message.push_plans) {
    PushPlan plan;
    plan.object_id = source.object_id;
    plan.contact_pose = {source.contact_x, source.contact_y, source.contact_heading};
    plan.expected_force_n = source.expected_force_n;
    plan.push_distance_m = source.push_distance_m;
    plan.travel_m = source.travel_m;
    plan.expected_cost = source.expected_cost;
    plan.affordance = source.affordance;
    for (const ifar::push_control_t& step : source.controls) {
      PushControl control;
      if (step.kind == ifar::push_control_t::KIND_PUSH) {
        control.kind = PushControlKind::Push;
      } else if (step.kind == ifar::push_control_t::KIND_SWITCH_CONTACT) {
        control.kind = PushControlKind::SwitchContact;
      } else {
        ++malformed;
        continue;
      }
      control.contact_edge = step.contact_edge;
      control.linear_velocity = step.linear_velocity;
      control.angular_velocity = step.angular_velocity;
      control.duration_s = step.duration_s;
      control.expected_vehicle_pose = {step.vehicle_x, step.vehicle_y, step.vehicle_heading};
      control.expected_object_pose = {step.object_x, step.object_y, step.object_heading};
      plan.controls.push_back(control);
    }
    path.push_plans.push_back(plan);
  }
  return path;
}

ForceReading fromMessage(const ifar::force_t& message)
{
  constexpr std::int32_t kUnusable =
      ifar::force_t::STATUS_FAULT | ifar::force_t::STATUS_SILENT | ifar::force_t::STATUS_COUNTER_STUCK;
  return {static_cast<double>(message.force_n), (message.status & kUnusable) != 0};
}

OdometryReading fromMessage(const ifar::odometry_t& message)
{
  return {message.linear_velocity, message.angular_velocity, message.status == 0};
}

EStopSignal fromMessage(const ifar::e_stop_t& message)
{
  return {message.engaged != 0, message.source, message.reason};
}

void MotorStatusCombiner::update(const ifar::motor_status_t& message, std::int64_t receive_utime)
{
  NodeState& node = nodes_[message.node_id];
  node.reading.heartbeat_ok = message.heartbeat_ok != 0;
  node.reading.fault = message.drive_state == ifar::motor_status_t::DRIVE_FAULT;
  node.reading.reason = message.reason;
  node.utime = receive_utime;
}

std::optional<Stamped<MotorReading>> MotorStatusCombiner::combined() const
{
  if (nodes_.empty()) {
    return std::nullopt;
  }
  Stamped<MotorReading> result;
  result.value.heartbeat_ok = true;
  result.utime = nodes_.begin()->second.utime;
  for (const auto& [node_id, node] : nodes_) {
    result.value.heartbeat_ok = result.value.heartbeat_ok && node.reading.heartbeat_ok;
    result.value.fault = result.value.fault || node.reading.fault;
    if (result.value.reason.empty() && !node.reading.reason.empty()) {
      result.value.reason = "node " + std::to_string(node_id) + ": " + node.reading.reason;
    }
    result.utime = std::min(result.utime, node.utime);
  }
  return result;
}

ifar::velocity_cmd_t toVelocityMessage(const Output& output, std::int64_t utime)
{
  ifar::velocity_cmd_t message;
  message.utime = utime;
  message.linear_velocity = output.command.linear;
  message.angular_velocity = output.command.angular;
  message.left_wheel = output.wheels.left;
  message.right_wheel = output.wheels.right;
  return message;
}

ifar::exec_status_t toStatusMessage(const Output& output, std::int64_t utime)
{
  const Status& status = output.status;
  ifar::exec_status_t message;
  message.utime = utime;
  message.mode = static_cast<std::int8_t>(status.mode);
  message.goal_id = status.goal_id;
  message.waypoint_index = status.waypoint_index;
  message.target_x = status.target.x();
  message.target_y = status.target.y();
  message.target_object_id = status.target_object_id;
  message.stale = status.stale;
  message.pushes = status.pushes;
  message.replans = status.replans;
  message.reason = status.reason;
  return message;
}

ifar::affordance_t toAffordanceMessage(const AffordanceEvent& event, std::int64_t utime)
{
  ifar::affordance_t message;
  message.utime = utime;
  message.object_id = event.object_id;
  message.pushable = event.pushable ? 1 : 0;
  message.push_force_n = event.push_force_n;
  message.affordance = event.affordance;
  message.planned_cost = event.planned_cost;
  message.measured_cost = event.measured_cost;
  switch (event.reason) {
    case AffordanceReason::NoMotion:
      message.reason = ifar::affordance_t::REASON_NO_MOTION;
      break;
    case AffordanceReason::CostHigher:
      message.reason = ifar::affordance_t::REASON_COST_HIGHER;
      break;
    case AffordanceReason::CostLower:
      message.reason = ifar::affordance_t::REASON_COST_LOWER;
      break;
    case AffordanceReason::Jammed:
      message.reason = ifar::affordance_t::REASON_JAMMED;
      break;
    case AffordanceReason::ContactNotReached:
      message.reason = ifar::affordance_t::REASON_CONTACT_NOT_REACHED;
      break;
  }
  return message;
}

ifar::blocked_passage_t toBlockedPassageMessage(const BlockedPassage& passage, std::int64_t utime)
{
  ifar::blocked_passage_t message;
  message.utime = utime;
  message.goal_id = passage.goal_id;
  message.from_x = passage.from.x();
  message.from_y = passage.from.y();
  message.to_x = passage.to.x();
  message.to_y = passage.to.y();
  message.stalls = passage.stalls;
  message.reason = passage.text;
  return message;
}

}  // namespace ifar::executive
