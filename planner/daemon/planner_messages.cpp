#include "planner/daemon/planner_messages.hpp"

#include <algorithm>

namespace ifar::planner {

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

PlannerMessages toMessages(const Planner& planner, const FrameResult& result, std::int64_t now_utime)
{
  PlannerMessages messages{};
  dv_graph_t& graph = messages.graph;
  graph.utime = result.status.utime;
  graph.sequence = result.sequence;
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    const perception::LayerPolygon& layer_polygon = result.polygons[index];
    polygon_t polygon{};
    polygon.id = static_cast<std::int64_t>(index) + 1;
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

  path_t& path = messages.path;
  path.utime = now_utime;
  path.goal_id = result.path.goal_id;
  path.sequence = result.sequence;
  path.valid = result.path.valid;
  path.length_m = result.path.length_m;
  path.cost = result.path.cost;
  for (const graph::PathPoint& point : result.path.waypoints) {
    waypoint_t waypoint{};
    waypoint.x = point.position.x();
    waypoint.y = point.position.y();
    const bool push = point.interaction != graph::kNoInteraction;
    waypoint.kind = push ? waypoint_t::KIND_PUSH : waypoint_t::KIND_FREE;
    if (!push && point.vertex != graph::kNoVertex) {
      const graph::Vertex* vertex = dv_graph.vertex(point.vertex);
      if (vertex != nullptr && vertex->kind == graph::VertexKind::TopologicalWaypoint) {
        waypoint.kind = waypoint_t::KIND_TOPOLOGICAL;
      }
    }
    waypoint.object_id = push ? point.object_id : -1;
    waypoint.push_plan_index = -1;  // push plans are not produced yet (interaction planner not wired in)
    path.waypoints.push_back(waypoint);
  }
  path.num_waypoints = static_cast<std::int32_t>(path.waypoints.size());
  path.num_push_plans = 0;

  messages.status = toStatusMessage(result.status);
  return messages;
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
