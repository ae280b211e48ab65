#pragma once
// The DV-graph (paper section V): vertices at convex polygon corners and topological waypoints (plus the
// robot and goal when a search attaches them), undirected visibility edges weighted by length, and
// directed interaction edges that carry a push plan's cost J. No LCM, no search state: a search works on
// an immutable SearchGraph snapshot, so the graph can be updated while a search runs on the last one.
//
// Vertex ids are stable: an id is never reused within one graph, and removal only marks the slot dead.

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"

namespace ifar::graph {

using VertexId = std::uint32_t;
constexpr VertexId kNoVertex = std::numeric_limits<VertexId>::max();

enum class VertexKind : std::uint8_t { Corner = 0, TopologicalWaypoint = 1, Robot = 2, Goal = 3 };

struct Vertex {
  VertexId id = kNoVertex;
  VertexKind kind = VertexKind::Corner;
  geometry::Point position = geometry::Point::Zero();
  // For corners: the polygon neighbours, so tangency can be re-tested after a merge.
  geometry::Point previous = geometry::Point::Zero();
  geometry::Point next = geometry::Point::Zero();
  std::int64_t object_id = 0;  // movable object the corner or waypoint belongs to; 0 = background
  int unseen_votes = 0;        // consecutive frames in view without being observed (merge voting)
  bool alive = true;
};

/// A directed edge that pushes object `object_id` out of the way: taken from `from` to `to` at cost J.
/// `push_plan` is a handle into the push plans the interaction planner keeps beside the graph.
struct InteractionEdge {
  VertexId from = kNoVertex;
  VertexId to = kNoVertex;
  std::int64_t object_id = 0;
  double cost = 0.0;
  std::uint32_t push_plan = 0;
  bool alive = true;
  // Where the push begins: the vehicle's position at first contact and the approach to it from `from`,
  // which J includes. A vehicle already nearer the contact than `from` is (mid-approach, or pushing when
  // the path is replanned) starts the push where it is; approach_m 0: not known, J as it stands.
  geometry::Point contact = geometry::Point::Zero();
  double approach_m = 0.0;
};

/// One end of an undirected visibility edge as seen from a vertex.
struct VisibilityLink {
  VertexId other = kNoVertex;
  double length = 0.0;
};

enum class EdgeStatus { Added, AlreadyPresent, Rejected };

class DvGraph {
 public:
  /// Adds a vertex and returns its new id (the `id` and `alive` fields of `vertex` are ignored).
  VertexId addVertex(const Vertex& vertex);
  /// Marks the vertex dead and drops its visibility and interaction edges. False for an unknown id.
  bool removeVertex(VertexId id);
  bool contains(VertexId id) const { return id < vertices_.size() && vertices_[id].alive; }
  /// nullptr for unknown or removed ids.
  const Vertex* vertex(VertexId id) const { return contains(id) ? &vertices_[id] : nullptr; }
  /// Moves a vertex (merge refinement); its edges' lengths are recomputed. False for an unknown id.
  bool moveVertex(VertexId id, const geometry::Point& position);
  /// Replaces position and corner neighbours (a fresher observation of the same corner).
  bool updateVertexGeometry(VertexId id, const geometry::Point& position, const geometry::Point& previous,
                            const geometry::Point& next);
  bool setUnseenVotes(VertexId id, int votes);

  /// Adds the undirected edge a-b weighted by the distance. Rejected for unknown ids, a == b.
  EdgeStatus addVisibilityEdge(VertexId a, VertexId b);
  bool removeVisibilityEdge(VertexId a, VertexId b);
  bool hasVisibilityEdge(VertexId a, VertexId b) const;
  /// Visibility neighbours of a live vertex (empty for unknown ids).
  const std::vector<VisibilityLink>& visibilityLinks(VertexId id) const;

  /// Adds a directed interaction edge; returns its index, or nullopt for unknown ids or a cost that is
  /// negative or not finite.
  std::optional<std::uint32_t> addInteractionEdge(const InteractionEdge& edge);
  /// Changes the cost J of an interaction edge (e.g. after the affordance estimate changed).
  bool setInteractionCost(std::uint32_t index, double cost);
  /// Removes every interaction edge of `object_id`; returns how many.
  std::size_t removeInteractionEdges(std::int64_t object_id);
  const std::vector<InteractionEdge>& interactionEdges() const { return interaction_edges_; }

  /// All vertex slots, dead ones included (check `alive`); index == id.
  const std::vector<Vertex>& vertexSlots() const { return vertices_; }
  std::size_t vertexCount() const { return live_vertices_; }
  std::size_t visibilityEdgeCount() const { return visibility_edges_; }
  std::size_t interactionEdgeCount() const;
  /// Heap bytes held (vertex slots, adjacency lists, interaction edges), by capacity.
  std::size_t memoryBytes() const;
  /// Gives back what the arrays hold beyond their contents (a map built once and planned on for long).
  void shrinkToFit();

 private:
  std::vector<Vertex> vertices_;
  std::vector<std::vector<VisibilityLink>> links_;
  std::vector<InteractionEdge> interaction_edges_;
  std::size_t live_vertices_ = 0;
  std::size_t visibility_edges_ = 0;
};

}  // namespace ifar::graph
