#include "planner/graph/visibility_builder.hpp"

namespace ifar::graph {

bool tangentAtBothEnds(const Vertex& first, const Vertex& second)
{
  const geometry::Vector direction = second.position - first.position;
  if (first.kind == VertexKind::Corner && !isTangent(cornerOf(first), direction)) {
    return false;
  }
  return second.kind != VertexKind::Corner || isTangent(cornerOf(second), -direction);
}

std::size_t connectByVisibility(const ObstacleSet& obstacles, DvGraph& graph, VertexId id)
{
  const Vertex* source = graph.vertex(id);
  if (source == nullptr) {
    return 0;
  }
  const Vertex from = *source;  // the slot vector may not move, but keep a copy to be safe
  BlockerCache cache;
  std::size_t added = 0;
  for (const auto& vertex : graph.vertexSlots()) {
    if (!vertex.alive || vertex.id == id || !tangentAtBothEnds(from, vertex) ||
        !obstacles.visible(from.position, vertex.position, cache)) {
      continue;
    }
    added += graph.addVisibilityEdge(id, vertex.id) == EdgeStatus::Added ? 1 : 0;
  }
  return added;
}

BuildStats addReducedVisibilityGraph(const ObstacleSet& obstacles, DvGraph& graph,
                                     std::vector<VertexId>* added, const ProgressCallback& progress)
{
  BuildStats stats;
  std::vector<LoopCorner> corners;
  std::vector<VertexId> ids;
  for (const auto& corner : obstacles.corners()) {
    if (!isConvexCorner(corner)) {
      continue;
    }
    Vertex vertex;
    vertex.kind = VertexKind::Corner;
    vertex.position = corner.position;
    vertex.previous = corner.previous;
    vertex.next = corner.next;
    vertex.object_id = obstacles.loops()[corner.loop].object_id;
    ids.push_back(graph.addVertex(vertex));
    corners.push_back(corner);
  }
  stats.corners = corners.size();
  const std::size_t count = corners.size();
  // Pair work shrinks with i; report progress by pairs done.
  const double total_pairs = 0.5 * static_cast<double>(count) * static_cast<double>(count + 1);
  double pairs_done = 0.0;
  double next_report = 0.05;
  for (std::size_t i = 0; i < count; ++i) {
    const LoopCorner& first = corners[i];
    // Lines from one corner in nearby directions are mostly blocked by the same wall: try that first.
    SectorBlockerCache blockers(first.position);
    for (std::size_t j = i + 1; j < count; ++j) {
      const LoopCorner& second = corners[j];
      const geometry::Vector direction = second.position - first.position;
      if (!isTangent(first, direction) || !isTangent(second, -direction)) {
        continue;
      }
      ++stats.tangent_pairs;
      if (obstacles.visibleFrom(second.position, blockers) &&
          graph.addVisibilityEdge(ids[i], ids[j]) == EdgeStatus::Added) {
        ++stats.edges;
      }
    }
    pairs_done += static_cast<double>(count - i);
    if (progress && total_pairs > 0.0 && pairs_done / total_pairs >= next_report) {
      progress(pairs_done / total_pairs);
      next_report += 0.05;
    }
  }
  if (added != nullptr) {
    *added = ids;
  }
  return stats;
}

}  // namespace ifar::graph
