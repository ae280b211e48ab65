#include "planner/graph/merge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace ifar::graph {
namespace {

std::int64_t cellKey(std::int64_t column, std::int64_t row)
{
  return column * 73856093LL ^ row * 19349663LL;
}

}  // namespace

LocalLayer toLocalLayer(const DvGraph& local_graph)
{
  LocalLayer layer;
  std::vector<std::size_t> index(local_graph.vertexSlots().size(), 0);
  for (const auto& vertex : local_graph.vertexSlots()) {
    if (vertex.alive) {
      index[vertex.id] = layer.vertices.size();
      layer.vertices.push_back(vertex);
    }
  }
  for (const auto& vertex : local_graph.vertexSlots()) {
    if (!vertex.alive) {
      continue;
    }
    for (const auto& link : local_graph.visibilityLinks(vertex.id)) {
      if (vertex.id < link.other) {
        layer.edges.emplace_back(index[vertex.id], index[link.other]);
      }
    }
  }
  return layer;
}

MergeStats mergeLocalIntoGlobal(const LocalLayer& local, const SensorView& view,
                                const GraphSettings& settings, DvGraph& global,
                                std::vector<VertexId>* local_to_global)
{
  MergeStats stats;
  const double cell = settings.association_distance_m;
  const auto cellOf = [cell](const geometry::Point& point) {
    return std::pair<std::int64_t, std::int64_t>(static_cast<std::int64_t>(std::floor(point.x() / cell)),
                                                 static_cast<std::int64_t>(std::floor(point.y() / cell)));
  };
  // Global vertices that could match (around the view and every local vertex), hashed by cell.
  double local_extent = view.radius;
  for (const auto& vertex : local.vertices) {
    if (vertex.position.allFinite()) {
      local_extent = std::max(local_extent, (vertex.position - view.centre).norm());
    }
  }
  std::unordered_map<std::int64_t, std::vector<VertexId>> buckets;
  const SensorView reach{view.centre, local_extent + settings.association_distance_m};
  for (const auto& vertex : global.vertexSlots()) {
    if (vertex.alive && reach.contains(vertex.position)) {
      const auto [column, row] = cellOf(vertex.position);
      buckets[cellKey(column, row)].push_back(vertex.id);
    }
  }

  std::unordered_set<VertexId> observed;
  std::vector<VertexId> mapping(local.vertices.size(), kNoVertex);
  for (std::size_t index = 0; index < local.vertices.size(); ++index) {
    const Vertex& candidate = local.vertices[index];
    if (!candidate.position.allFinite() || !candidate.previous.allFinite() || !candidate.next.allFinite()) {
      ++stats.skipped;
      continue;
    }
    const auto [column, row] = cellOf(candidate.position);
    VertexId best = kNoVertex;
    double best_distance = settings.association_distance_m;
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const auto found = buckets.find(cellKey(column + dx, row + dy));
        if (found == buckets.end()) {
          continue;
        }
        for (const VertexId id : found->second) {
          const Vertex* vertex = global.vertex(id);
          if (vertex == nullptr || vertex->kind != candidate.kind || observed.count(id) != 0) {
            continue;
          }
          const double distance = (vertex->position - candidate.position).norm();
          if (distance <= best_distance) {
            best_distance = distance;
            best = id;
          }
        }
      }
    }
    if (best != kNoVertex) {
      global.updateVertexGeometry(best, candidate.position, candidate.previous, candidate.next);
      global.setUnseenVotes(best, 0);
      ++stats.associated;
    } else {
      Vertex added = candidate;
      added.unseen_votes = 0;
      best = global.addVertex(added);
      ++stats.added;
    }
    observed.insert(best);
    mapping[index] = best;
  }

  // Voting: in view, not observed this frame.
  std::vector<VertexId> to_remove;
  for (const auto& vertex : global.vertexSlots()) {
    if (!vertex.alive || observed.count(vertex.id) != 0 || !view.contains(vertex.position)) {
      continue;
    }
    const int votes = vertex.unseen_votes + 1;
    if (votes >= settings.votes) {
      to_remove.push_back(vertex.id);
    } else {
      global.setUnseenVotes(vertex.id, votes);
      ++stats.voted;
    }
  }
  for (const VertexId id : to_remove) {
    global.removeVertex(id);
    ++stats.removed;
  }

  // Edges among the vertices observed this frame follow the local layer.
  std::unordered_set<std::uint64_t> local_edges;
  const auto edgeKey = [](VertexId a, VertexId b) {
    if (a > b) {
      std::swap(a, b);
    }
    return (static_cast<std::uint64_t>(a) << 32) | b;
  };
  for (const auto& [first, second] : local.edges) {
    if (first >= mapping.size() || second >= mapping.size() || mapping[first] == kNoVertex ||
        mapping[second] == kNoVertex) {
      ++stats.skipped;
      continue;
    }
    local_edges.insert(edgeKey(mapping[first], mapping[second]));
    if (global.addVisibilityEdge(mapping[first], mapping[second]) == EdgeStatus::Added) {
      ++stats.edges_added;
    }
  }
  std::vector<std::pair<VertexId, VertexId>> contradicted;
  for (const VertexId id : observed) {
    for (const auto& link : global.visibilityLinks(id)) {
      if (id < link.other && observed.count(link.other) != 0 &&
          local_edges.count(edgeKey(id, link.other)) == 0) {
        contradicted.emplace_back(id, link.other);
      }
    }
  }
  for (const auto& [first, second] : contradicted) {
    if (global.removeVisibilityEdge(first, second)) {
      ++stats.edges_removed;
    }
  }
  if (local_to_global != nullptr) {
    *local_to_global = std::move(mapping);
  }
  return stats;
}

}  // namespace ifar::graph
