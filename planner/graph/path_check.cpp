#include "planner/graph/path_check.hpp"

#include <algorithm>

namespace ifar::graph {
namespace {

/// True when `obstacles` block the segment from `from` to `to` between points `end_margin` (at most a
/// quarter of its length) in from each end.
bool blockedInside(const geometry::Point& from, const geometry::Point& to, const ObstacleSet& obstacles,
                   double end_margin)
{
  const geometry::Vector step = to - from;
  const double length = step.norm();
  if (length <= 0.0) {
    return false;
  }
  const geometry::Vector inward = step * (std::min(end_margin, 0.25 * length) / length);
  return !obstacles.visible(from + inward, to - inward);
}

}  // namespace

std::vector<std::pair<VertexId, VertexId>> blockedPathEdges(const std::vector<PathPoint>& path,
                                                            const ObstacleSet& obstacles, double end_margin)
{
  std::vector<std::pair<VertexId, VertexId>> blocked;
  for (std::size_t index = 1; index < path.size(); ++index) {
    const PathPoint& from = path[index - 1];
    const PathPoint& to = path[index];
    if (from.vertex == kNoVertex || to.vertex == kNoVertex || to.interaction != kNoInteraction) {
      continue;
    }
    if (blockedInside(from.position, to.position, obstacles, end_margin)) {
      blocked.emplace_back(from.vertex, to.vertex);
    }
  }
  return blocked;
}

std::vector<std::pair<VertexId, VertexId>> blockedEdgesOf(const DvGraph& graph, VertexId vertex,
                                                          const ObstacleSet& obstacles, double end_margin)
{
  std::vector<std::pair<VertexId, VertexId>> blocked;
  const Vertex* from = graph.vertex(vertex);
  if (from == nullptr) {
    return blocked;
  }
  for (const VisibilityLink& link : graph.visibilityLinks(vertex)) {
    const Vertex* to = graph.vertex(link.other);
    if (to != nullptr && blockedInside(from->position, to->position, obstacles, end_margin)) {
      blocked.emplace_back(vertex, link.other);
    }
  }
  return blocked;
}

}  // namespace ifar::graph
