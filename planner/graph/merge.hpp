#pragma once
// Local-global merge (paper Algorithm 1). Each frame the local layer's graph (built from the current
// scan's polygons) is merged into the global graph:
//  - a local vertex within `association_distance_m` of a global vertex of the same kind is that vertex:
//    its geometry is refreshed and its unseen votes reset;
//  - other local vertices are added;
//  - a global vertex inside the view that no local vertex matched gets one unseen vote and is removed
//    after `votes` consecutive ones; vertices outside the view are left alone;
//  - edges: local visibility edges are added between the matched global vertices; a global edge between
//    two vertices observed this frame that the local layer does not have is removed (the observation
//    contradicts it). Edges to vertices not observed this frame stay: unknown space is attemptable.

#include <cstddef>
#include <utility>
#include <vector>

#include "planner/graph/dv_graph.hpp"
#include "planner/graph/settings.hpp"

namespace ifar::graph {

/// One frame's local graph in the world frame.
struct LocalLayer {
  std::vector<Vertex> vertices;                            // id and alive are ignored
  std::vector<std::pair<std::size_t, std::size_t>> edges;  // visibility edges, indices into vertices
};

/// The live part of a DvGraph as a LocalLayer (e.g. the graph built from this frame's polygons).
LocalLayer toLocalLayer(const DvGraph& local_graph);

struct SensorView {
  geometry::Point centre = geometry::Point::Zero();  // robot position, world frame
  double radius = 0.0;                               // metres
  bool contains(const geometry::Point& point) const { return (point - centre).norm() <= radius; }
};

struct MergeStats {
  std::size_t associated = 0;
  std::size_t added = 0;
  std::size_t voted = 0;  // in view, unmatched, kept for now
  std::size_t removed = 0;
  std::size_t edges_added = 0;
  std::size_t edges_removed = 0;
  std::size_t skipped = 0;  // local vertices or edges with non-finite or out-of-range data
};

/// Merges `local` into `global`. `local_to_global`, when not null, receives the global id of every
/// local vertex (kNoVertex for skipped ones).
MergeStats mergeLocalIntoGlobal(const LocalLayer& local, const SensorView& view,
                                const GraphSettings& settings, DvGraph& global,
                                std::vector<VertexId>* local_to_global = nullptr);

}  // namespace ifar::graph
