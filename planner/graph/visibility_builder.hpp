#pragma once
// Builds the reduced visibility graph of an obstacle set: vertices at convex corners, an edge between
// two corners only when the line is tangent at both ends and the segment is visible.

#include <cstddef>
#include <functional>
#include <vector>

#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"

namespace ifar::graph {

struct BuildStats {
  std::size_t corners = 0;        // convex corners added as vertices
  std::size_t tangent_pairs = 0;  // pairs that passed the tangency filter
  std::size_t edges = 0;          // visibility edges added
};

/// Called with the fraction done (0..1) now and then during a long build; may be empty.
using ProgressCallback = std::function<void(double)>;

/// Adds every convex corner of `obstacles` to `graph` (kind Corner, object id of its loop) and the
/// visibility edges between them. Returns the ids of the added corners in `added` when not null. The
/// visibility tests run on `threads` threads (the calling one included); the graph is the same for any
/// number. `progress` is called on the calling thread.
BuildStats addReducedVisibilityGraph(const ObstacleSet& obstacles, DvGraph& graph,
                                     std::vector<VertexId>* added = nullptr,
                                     const ProgressCallback& progress = {}, unsigned threads = 1);

/// Adds visibility edges from vertex `id` (e.g. a new topological waypoint) to every live vertex it sees,
/// keeping the reduced-graph tangency rule at corner ends. Returns the number of edges added.
std::size_t connectByVisibility(const ObstacleSet& obstacles, DvGraph& graph, VertexId id);

/// The corner geometry of a graph vertex, for tangency tests.
inline LoopCorner cornerOf(const Vertex& vertex)
{
  return LoopCorner{vertex.position, vertex.previous, vertex.next, 0};
}

/// True when an edge between these two vertices would be kept by the reduced visibility graph:
/// tangent at both ends when they are corners (waypoints, robot and goal need no tangency).
bool tangentAtBothEnds(const Vertex& first, const Vertex& second);

}  // namespace ifar::graph
