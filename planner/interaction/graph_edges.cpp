#include "planner/interaction/graph_edges.hpp"

namespace ifar::interaction {

InsertedInteractions insertInteractions(graph::DvGraph& graph, std::int64_t object_id,
                                        const ObjectInteractions& interactions,
                                        std::uint32_t first_plan_handle)
{
  InsertedInteractions inserted;
  graph.removeInteractionEdges(object_id);
  for (const TopologicalWaypoint& waypoint : interactions.connectivity.waypoints) {
    graph::Vertex vertex;
    vertex.kind = graph::VertexKind::TopologicalWaypoint;
    vertex.position = waypoint.position;
    vertex.object_id = object_id;
    inserted.waypoint_vertices.push_back(graph.addVertex(vertex));
  }
  for (std::size_t index = 0; index < interactions.plans.size(); ++index) {
    const PairPlan& pair = interactions.plans[index];
    if (pair.plan.status != PlanStatus::Found || pair.pair.from >= inserted.waypoint_vertices.size() ||
        pair.pair.to >= inserted.waypoint_vertices.size()) {
      ++inserted.plans_without_edge;
      continue;
    }
    graph::InteractionEdge edge;
    edge.from = inserted.waypoint_vertices[pair.pair.from];
    edge.to = inserted.waypoint_vertices[pair.pair.to];
    edge.object_id = object_id;
    edge.cost = pair.plan.cost;
    edge.push_plan = first_plan_handle + static_cast<std::uint32_t>(index);
    edge.contact = pair.plan.contact_pose.position();
    edge.approach_m = pair.plan.approach_distance_m;
    if (const auto added = graph.addInteractionEdge(edge)) {
      inserted.edges.push_back(*added);
    } else {
      ++inserted.plans_without_edge;
    }
  }
  return inserted;
}

}  // namespace ifar::interaction
