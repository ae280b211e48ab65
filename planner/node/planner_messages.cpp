#include "planner/node/planner_messages.hpp"

#include <algorithm>

namespace ifar::planner {

void stampPath(path_t& path, std::int64_t now_utime)
{
  path.utime = now_utime;
  for (push_plan_t& plan : path.push_plans) {
    plan.utime = now_utime;
  }
}

push_plan_t toPushPlanMessage(const PathPush& push)
{
  const interaction::PushPlan& plan = push.plan;
  push_plan_t message{};
  message.object_id = push.object_id;
  message.from_vertex =
      push.from_vertex == graph::kNoVertex ? -1 : static_cast<std::int64_t>(push.from_vertex);
  message.to_vertex = push.to_vertex == graph::kNoVertex ? -1 : static_cast<std::int64_t>(push.to_vertex);
  message.contact_edge = static_cast<std::int32_t>(plan.contact_edge);
  message.contact_x = plan.contact_pose.x;
  message.contact_y = plan.contact_pose.y;
  message.contact_heading = plan.contact_pose.heading;
  const geometry::Pose2& start = plan.start_object_pose;
  for (const interaction::PushControl& control : plan.controls) {
    push_control_t out{};
    const bool switch_contact = control.kind == interaction::ControlKind::ContactSwitch;
    out.kind = switch_contact ? push_control_t::KIND_SWITCH_CONTACT : push_control_t::KIND_PUSH;
    out.contact_edge = static_cast<std::int32_t>(control.contact_edge);
    out.linear_velocity = control.linear_mps;
    out.angular_velocity = control.angular_radps;
    out.duration_s = control.duration_s;
    out.vehicle_x = control.vehicle_pose.x;
    out.vehicle_y = control.vehicle_pose.y;
    out.vehicle_heading = control.vehicle_pose.heading;
    out.object_x = control.object_pose.x;
    out.object_y = control.object_pose.y;
    // push_control_t: the object's rotation from its pose at planning time.
    out.object_heading = geometry::wrapAngle(control.object_pose.heading - start.heading);
    message.controls.push_back(out);
  }
  message.num_controls = static_cast<std::int32_t>(message.controls.size());
  message.expected_force_n = plan.expected_force_n;
  message.push_distance_m = plan.push_distance_m;
  message.travel_m = plan.travel_distance_m;
  message.expected_cost = plan.cost;
  message.affordance = push.affordance;
  return message;
}

planner_status_t toStatusMessage(const PlannerStatus& status)
{
  planner_status_t message{};
  message.utime = status.utime;
  message.state = static_cast<std::int8_t>(status.state);
  message.flags = status.flags;
  message.frames = status.frames;
  message.perception_ms = static_cast<float>(status.timings.perception_ms);
  message.local_graph_ms = static_cast<float>(status.timings.local_graph_ms);
  message.merge_ms = static_cast<float>(status.timings.merge_ms);
  message.interaction_ms = static_cast<float>(status.timings.interaction_ms);
  message.search_ms = static_cast<float>(status.timings.search_ms);
  message.total_ms = static_cast<float>(status.timings.total_ms);
  message.num_points = static_cast<std::int32_t>(status.obstacle_points);
  message.num_polygons = static_cast<std::int32_t>(status.polygons);
  message.num_vertices = static_cast<std::int32_t>(status.vertices);
  message.num_edges = static_cast<std::int32_t>(status.edges);
  message.num_interaction_edges = static_cast<std::int32_t>(status.interaction_edges);
  message.bad_inputs = status.bad_inputs;
  message.message = status.message;
  return message;
}

dv_graph_t toGraphMessage(const Planner& planner, const FrameResult& result)
{
  dv_graph_t graph{};
  graph.utime = result.status.utime;
  graph.sequence = result.sequence;
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    const perception::LayerPolygon& layer_polygon = result.polygons[index];
    polygon_t polygon{};
    const std::int64_t object_id = index < result.polygon_ids.size() ? result.polygon_ids[index] : 0;
    polygon.id = object_id > 0 ? object_id : kBackgroundPolygonIdBase + static_cast<std::int64_t>(index);
    polygon.kind = layer_polygon.obstacle_class == perception::ObstacleClass::Movable
                       ? polygon_t::KIND_MOVABLE
                       : polygon_t::KIND_BACKGROUND;
    // Convention (polygon_t has no hole flag): outer borders counter-clockwise, free-space holes
    // clockwise, so the blocked side is always on the left and viewers can tell them apart.
    const bool hole = layer_polygon.boundary == perception::BoundaryKind::Hole;
    const std::size_t count = layer_polygon.vertices.size();
    for (std::size_t vertex = 0; vertex < count; ++vertex) {
      const geometry::Point& point = layer_polygon.vertices[hole ? count - 1 - vertex : vertex];
      polygon.x.push_back(point.x());
      polygon.y.push_back(point.y());
    }
    polygon.num_points = static_cast<std::int32_t>(polygon.x.size());
    graph.polygons.push_back(std::move(polygon));
  }
  graph.num_polygons = static_cast<std::int32_t>(graph.polygons.size());
  const graph::DvGraph& dv_graph = planner.graph();
  for (const graph::Vertex& vertex : dv_graph.vertexSlots()) {
    if (!vertex.alive) {
      continue;
    }
    graph_vertex_t out{};
    out.id = vertex.id;
    out.kind = static_cast<std::int8_t>(vertex.kind);
    out.x = vertex.position.x();
    out.y = vertex.position.y();
    out.polygon_id = vertex.object_id > 0 ? vertex.object_id : -1;
    graph.vertices.push_back(out);
    for (const graph::VisibilityLink& link : dv_graph.visibilityLinks(vertex.id)) {
      if (link.other > vertex.id) {  // each undirected edge once
        graph_edge_t edge{};
        edge.from_id = vertex.id;
        edge.to_id = link.other;
        edge.kind = graph_edge_t::KIND_VISIBILITY;
        edge.cost = link.length;
        edge.object_id = -1;
        graph.edges.push_back(edge);
      }
    }
  }
  for (const graph::InteractionEdge& interaction : dv_graph.interactionEdges()) {
    if (!interaction.alive) {
      continue;
    }
    graph_edge_t edge{};
    edge.from_id = interaction.from;
    edge.to_id = interaction.to;
    edge.kind = graph_edge_t::KIND_INTERACTION;
    edge.cost = interaction.cost;
    edge.object_id = interaction.object_id;
    graph.edges.push_back(edge);
  }
  graph.num_vertices = static_cast<std::int32_t>(graph.vertices.size());
  graph.num_edges = static_cast<std::int32_t>(graph.edges.size());

  return graph;
}

path_t toPathMessage(const graph::DvGraph& dv_graph, const FrameResult& result, std::int64_t now_utime)
{
  path_t path{};
  path.goal_id = result.path.goal_id;
  path.sequence = result.sequence;
  path.valid = result.path.valid;
  path.length_m = result.path.length_m;
  path.cost = result.path.cost;
  for (const PathPush& push : result.path.pushes) {
    path.push_plans.push_back(toPushPlanMessage(push));
  }
  stampPath(path, now_utime);
  path.num_push_plans = static_cast<std::int32_t>(path.push_plans.size());
  for (std::size_t index = 0; index < result.path.waypoints.size(); ++index) {
    const graph::PathPoint& point = result.path.waypoints[index];
    waypoint_t waypoint{};
    waypoint.x = point.position.x();
    waypoint.y = point.position.y();
    waypoint.kind = waypoint_t::KIND_FREE;
    waypoint.object_id = -1;
    waypoint.push_plan_index = -1;
    if (point.vertex != graph::kNoVertex) {
      const graph::Vertex* vertex = dv_graph.vertex(point.vertex);
      if (vertex != nullptr && vertex->kind == graph::VertexKind::TopologicalWaypoint) {
        waypoint.kind = waypoint_t::KIND_TOPOLOGICAL;
      }
    }
    for (std::size_t push = 0; push < result.path.pushes.size(); ++push) {
      if (result.path.pushes[push].to_waypoint == index) {
        waypoint.kind = waypoint_t::KIND_PUSH;
        waypoint.object_id = result.path.pushes[push].object_id;
        waypoint.push_plan_index = static_cast<std::int32_t>(push);
      }
    }
    path.waypoints.push_back(waypoint);
  }
  path.num_waypoints = static_cast<std::int32_t>(path.waypoints.size());

  return path;
}

PlannerMessages toMessages(const Planner& planner, const FrameResult& result, std::int64_t now_utime)
{
  return PlannerMessages{toGraphMessage(planner, result), toPathMessage(planner.graph(), result, now_utime),
                         toStatusMessage(result.status)};
}

AffordanceUpdate toAffordanceUpdate(const affordance_t& message)
{
  AffordanceUpdate update;
  update.object_id = message.object_id;
  update.pushable = message.pushable;
  update.push_force_n = message.push_force_n;
  update.affordance = message.affordance;
  update.contact_not_reached = message.reason == affordance_t::REASON_CONTACT_NOT_REACHED;
  return update;
}

BlockedPassage toBlockedPassage(const blocked_passage_t& message)
{
  BlockedPassage passage;
  passage.from = geometry::Point(message.from_x, message.from_y);
  passage.to = geometry::Point(message.to_x, message.to_y);
  return passage;
}

PoseSample toPoseSample(const pose_t& pose)
{
  PoseSample sample;
  sample.utime = pose.utime;
  sample.position = Eigen::Vector3d(pose.position[0], pose.position[1], pose.position[2]);
  // Eigen's constructor takes w, x, y, z in that order, as pose_t stores them.
  sample.orientation =
      Eigen::Quaterniond(pose.orientation[0], pose.orientation[1], pose.orientation[2], pose.orientation[3]);
  return sample;
}

std::vector<geometry::Polygon> toPolygons(const object_polygons_t& message, std::int64_t& skipped)
{
  std::vector<geometry::Polygon> polygons;
  for (const polygon_t& polygon : message.polygons) {
    const std::size_t count = static_cast<std::size_t>(std::max(polygon.num_points, 0));
    if (count < 3 || polygon.x.size() != count || polygon.y.size() != count) {
      ++skipped;
      continue;
    }
    geometry::Polygon outline;
    bool finite = true;
    for (std::size_t index = 0; index < count; ++index) {
      outline.emplace_back(polygon.x[index], polygon.y[index]);
      finite = finite && outline.back().allFinite();
    }
    if (!finite) {
      ++skipped;
      continue;
    }
    polygons.push_back(std::move(outline));
  }
  return polygons;
}

}  // namespace ifar::planner
