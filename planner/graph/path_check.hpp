#pragma once
// Checks a found path's graph edges against the obstacles of the moment. The merge drops a visibility
// edge only when both its ends are observed in one frame, so an edge to a vertex out of view outlives an
// obstacle that has grown across it since (a wall seen anew, a raster that differs from the prior map by
// a cell). Checking only the edges a search takes, after it took them, keeps the search as fast as before.

#include <utility>
#include <vector>

#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/search.hpp"

namespace ifar::graph {

/// The visibility steps of `path` between two graph vertices (pushes, the robot's link and the goal's,
/// which the search tests itself, are left out) that `obstacles` block between points `end_margin` in
/// from each end (at most a quarter of the step): a vertex refreshed from a slightly different outline
/// may sit a few centimetres inside it, which is no reason to drop the edge.
std::vector<std::pair<VertexId, VertexId>> blockedPathEdges(const std::vector<PathPoint>& path,
                                                            const ObstacleSet& obstacles, double end_margin);

/// Every visibility edge of `vertex` that `obstacles` block, tested as above. Where one edge of a vertex
/// is stale, others usually are too (the vertex's wall was seen anew and the vertex waits out its unseen
/// votes), and each would otherwise cost the search another round.
std::vector<std::pair<VertexId, VertexId>> blockedEdgesOf(const DvGraph& graph, VertexId vertex,
                                                          const ObstacleSet& obstacles, double end_margin);

}  // namespace ifar::graph
