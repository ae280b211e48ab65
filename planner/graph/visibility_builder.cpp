#include "planner/graph/visibility_builder.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>

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

namespace {

/// The corners after `first` (indices into `corners`) that `first` sees along a line tangent at both
/// ends, and how many pairs were tangent.
struct RowResult {
  std::vector<std::uint32_t> visible;
  std::size_t tangent_pairs = 0;
};

/// The convex corners of a build in the layout the pair loop streams through: positions and arms apart,
/// each worked out once instead of once per pair.
struct CornerTable {
  std::vector<geometry::Point> positions;
  std::vector<CornerArms> arms;
};

RowResult visibleAfter(const ObstacleSet& obstacles, const CornerTable& corners, std::size_t first)
{
  RowResult row;
  const geometry::Point from = corners.positions[first];
  const CornerArms& from_arms = corners.arms[first];
  // Lines from one corner in nearby directions are mostly blocked by the same wall: try that first.
  SectorBlockerCache blockers(from);
  const std::size_t count = corners.positions.size();
  for (std::size_t second = first + 1; second < count; ++second) {
    const geometry::Vector direction = corners.positions[second] - from;
    if (!isTangent(from_arms, direction) || !isTangent(corners.arms[second], -direction)) {
      continue;
    }
    ++row.tangent_pairs;
    if (obstacles.visibleFrom(corners.positions[second], blockers)) {
      row.visible.push_back(static_cast<std::uint32_t>(second));
    }
  }
  return row;
}

}  // namespace

BuildStats addReducedVisibilityGraph(const ObstacleSet& obstacles, DvGraph& graph,
                                     std::vector<VertexId>* added, const ProgressCallback& progress,
                                     unsigned threads)
{
  BuildStats stats;
  CornerTable corners;
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
    corners.positions.push_back(corner.position);
    corners.arms.push_back(CornerArms::of(corner));
  }
  stats.corners = corners.positions.size();
  const std::size_t count = stats.corners;
  // Rows (one corner against every later one) are tested on `threads` threads, each taking the next row
  // not yet taken; the edges are then added row by row, so the graph is the same for any thread count.
  std::vector<RowResult> rows(count);
  std::atomic<std::size_t> next_row{0};
  std::atomic<std::size_t> pairs_done{0};
  // Takes rows until none is left; gives `row_done`, when set, the fraction of pairs done after each (a
  // row's work shrinks with its index).
  const double total_pairs = 0.5 * static_cast<double>(count) * static_cast<double>(count + 1);
  const auto work = [&](const ProgressCallback& row_done) {
    for (std::size_t row = next_row++; row < count; row = next_row++) {
      rows[row] = visibleAfter(obstacles, corners, row);
      const std::size_t done = pairs_done += count - row;
      if (row_done) {
        row_done(static_cast<double>(done) / total_pairs);
      }
    }
  };
  std::vector<std::thread> helpers;
  for (unsigned helper = 1; helper < std::max(1U, threads) && helper < count; ++helper) {
    helpers.emplace_back(work, ProgressCallback());
  }
  // This thread works too, and alone reports progress.
  double next_report = 0.05;
  double reported = 0.0;
  work([&](double done) {
    if (progress && done >= next_report) {
      progress(done);
      reported = done;
      next_report += 0.05;
    }
  });
  for (std::thread& helper : helpers) {
    helper.join();
  }
  if (progress && count > 0 && reported < 1.0) {
    progress(1.0);  // the helpers may have taken the last rows (or all of them)
  }
  for (std::size_t row = 0; row < count; ++row) {
    stats.tangent_pairs += rows[row].tangent_pairs;
    for (const std::uint32_t other : rows[row].visible) {
      if (graph.addVisibilityEdge(ids[row], ids[other]) == EdgeStatus::Added) {
        ++stats.edges;
      }
    }
  }
  if (added != nullptr) {
    *added = ids;
  }
  return stats;
}

}  // namespace ifar::graph
