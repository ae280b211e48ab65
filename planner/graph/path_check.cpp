#include "planner/graph/path_check.hpp"

#include <algorithm>

namespace ifar::graph {

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
    const geometry::Vector step = to.position - from.position;
    const double length = step.norm();
    if (length <= 0.0) {
      continue;
    }
    const double margin = std::min(end_margin, 0.25 * length);
    const geometry::Vector inward = step * (margin / length);
    if (!obstacles.visible(from.position + inward, to.position - inward)) {
      blocked.emplace_back(from.vertex, to.vertex);
    }
  }
  return blocked;
}

}  // namespace ifar::graph
