#include "sim/runner/path_conversion.hpp"

namespace ifar::runner {

executive::PushPlan toExecutivePushPlan(const planner::PathPush& push)
{
  const interaction::PushPlan& source = push.plan;
  executive::PushPlan plan;
  plan.object_id = push.object_id;
  plan.contact_pose = source.contact_pose;
  plan.expected_force_n = source.expected_force_n;
  plan.push_distance_m = source.push_distance_m;
  plan.travel_m = source.travel_distance_m;
  plan.expected_cost = source.cost;
  plan.affordance = push.affordance;
  plan.controls.reserve(source.controls.size());
  for (const interaction::PushControl& step : source.controls) {
    executive::PushControl control;
    control.kind = step.kind == interaction::ControlKind::ContactSwitch
                       ? executive::PushControlKind::SwitchContact
                       : executive::PushControlKind::Push;
    control.contact_edge = static_cast<int>(step.contact_edge);
    control.linear_velocity = step.linear_mps;
    control.angular_velocity = step.angular_radps;
    control.duration_s = step.duration_s;
    control.expected_vehicle_pose = step.vehicle_pose;
    // As push_control_t carries it: the centroid, and the heading change since planning time.
    control.expected_object_pose = {
        step.object_pose.x, step.object_pose.y,
        geometry::wrapAngle(step.object_pose.heading - source.start_object_pose.heading)};
    plan.controls.push_back(control);
  }
  return plan;
}

executive::Path toExecutivePath(const planner::PlannedPath& path, const graph::DvGraph& graph,
                                std::int64_t utime, std::int64_t sequence)
{
  executive::Path out;
  out.utime = utime;
  out.goal_id = path.goal_id;
  out.sequence = sequence;
  out.valid = path.valid;
  out.waypoints.reserve(path.waypoints.size());
  for (const graph::PathPoint& point : path.waypoints) {
    executive::Waypoint waypoint;
    waypoint.position = point.position;
    if (point.vertex != graph::kNoVertex) {
      const graph::Vertex* vertex = graph.vertex(point.vertex);
      if (vertex != nullptr && vertex->kind == graph::VertexKind::TopologicalWaypoint) {
        waypoint.kind = executive::WaypointKind::Topological;
      }
    }
    out.waypoints.push_back(waypoint);
  }
  // As the planner daemon: the waypoint a push reaches is Push with the object and its plan; the one
  // where it starts is a topological graph vertex, which the executive pairs with the next waypoint's plan.
  out.push_plans.reserve(path.pushes.size());
  for (const planner::PathPush& push : path.pushes) {
    const int plan_index = static_cast<int>(out.push_plans.size());
    out.push_plans.push_back(toExecutivePushPlan(push));
    if (push.to_waypoint < out.waypoints.size()) {
      executive::Waypoint& end = out.waypoints[push.to_waypoint];
      end.kind = executive::WaypointKind::Push;
      end.object_id = push.object_id;
      end.push_plan_index = plan_index;
    }
  }
  return out;
}

}  // namespace ifar::runner
