#pragma once
// Global search (paper VII.A): attach the robot and the goal to the graph through visibility, then A*
// with the Euclidean heuristic. Both attachments are lazy: a link is tested for visibility only when A*
// could use it, so a short query on a large map tests few lines. The search reads an immutable SearchGraph
// snapshot and keeps its state in a SearchScratch the caller owns, so graph updates and searches can run
// concurrently and repeated searches allocate nothing once the scratch has grown.
//
// Unknown space is attemptable: the obstacle set holds only observed obstacles, so attachments and
// edges that cross unobserved space count as free until perception adds a polygon that blocks them.

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry/point.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"

namespace ifar::graph {

constexpr std::uint32_t kNoInteraction = std::numeric_limits<std::uint32_t>::max();

/// Compressed, read-only copy of a DvGraph's live part: dense indices, arcs in flat arrays.
class SearchGraph {
 public:
  SearchGraph() = default;
  static SearchGraph fromDvGraph(const DvGraph& graph);
  /// A snapshot of `graph`, which must be the complete reduced visibility graph of `obstacles`: every
  /// convex corner, and an edge for every pair of them tangent at both ends that see each other, as
  /// addReducedVisibilityGraph builds it (vertices and edges neither added nor removed since; topological
  /// waypoints may be added), over loops that do not cross one another (as traced from a grid, so every
  /// corner of the blocked region is a loop vertex). Every shortest path is then a path of this graph that
  /// bends only where it wraps a corner, so a search without route preference or surcharge skips, at a corner
  /// it reached from a parent, the arcs and the goal link that would bend away from the corner's obstacle
  /// (isTautBend): same costs as fromDvGraph, with fewer arcs relaxed and fewer goal lines tested. Corners
  /// that share their position with another obstacle vertex, and graphs with interaction edges (a push's cost
  /// is not its length), are searched without it.
  static SearchGraph fromCompleteGraph(const DvGraph& graph, const ObstacleSet& obstacles);

  std::size_t size() const { return positions_.size(); }
  std::size_t arcCount() const { return targets_.size(); }
  /// Heap bytes held (vertices, arcs, the vertex grid), by capacity.
  std::size_t memoryBytes() const;

 private:
  friend class AStarSearch;
  void buildVertexGrid();
  std::uint32_t interactionOf(std::uint32_t arc) const
  {
    return interaction_.empty() ? kNoInteraction : interaction_[arc];
  }
  void sortArcsAroundCorners();

  std::vector<VertexId> ids_;
  std::vector<std::uint32_t> index_of_;  // VertexId -> dense index; the uint32 maximum for dead ids
  std::vector<geometry::Point> positions_;
  std::vector<geometry::Point> previous_;
  std::vector<geometry::Point> next_;
  std::vector<VertexKind> kinds_;
  // Per vertex: 1 for a corner at which a search may skip the bends that do not wrap it (see
  // fromCompleteGraph); empty for a graph that is not known to be complete.
  std::vector<std::uint8_t> taut_only_;
  // Per such corner, its arcs in three runs: [offsets_[v], left_end_[v]) leave with the corner's wedge on
  // their left, ordered clockwise from the next edge's direction; [left_end_[v], right_end_[v]) with it on
  // their right, counter-clockwise from the previous edge's direction; the rest undecided.
  std::vector<std::uint32_t> left_end_;
  std::vector<std::uint32_t> right_end_;
  std::vector<std::uint32_t> offsets_;  // arcs of vertex v: [offsets_[v], offsets_[v + 1])
  std::vector<std::uint32_t> targets_;
  std::vector<double> costs_;
  // Per arc, its interaction edge index or kNoInteraction; empty when no arc is a push.
  std::vector<std::uint32_t> interaction_;
  std::vector<std::int64_t> interaction_objects_;
  std::vector<std::uint32_t> interaction_plans_;
  std::vector<geometry::Point> interaction_contacts_;  // InteractionEdge::contact
  std::vector<double> interaction_approaches_;         // InteractionEdge::approach_m
  // Uniform grid over the vertex positions (vertices of cell c: cell_vertices_[cell_offsets_[c] ..
  // cell_offsets_[c + 1])), for attaching the robot in order of A* priority.
  geometry::Point cell_origin_ = geometry::Point::Zero();
  double cell_size_ = 1.0;
  int cell_columns_ = 0;
  int cell_rows_ = 0;
  std::vector<std::uint32_t> cell_offsets_;
  std::vector<std::uint32_t> cell_vertices_;
};

enum class SearchStatus {
  Found,
  NoPath,        // start and goal valid but not connected
  InvalidStart,  // NaN or infinite coordinates
  InvalidGoal,
  StartOffMap,  // outside the prior map's bounds
  GoalOffMap,
  StartInObstacle,  // strictly inside a blocked region, and the query asked not to snap
  GoalInObstacle,
};

const char* toString(SearchStatus status);

/// The exit code of a command whose query ended with `status`, the same in every command that answers
/// path queries: 0 found, 1 no path, 2 bad input (a point that is not finite or off the map, as a bad
/// command line), 4 start inside an obstacle, 5 goal inside an obstacle.
int exitCodeOf(SearchStatus status);

/// What a search does with a start or goal strictly inside an obstacle.
enum class InsideObstacle {
  Snap,    // move it to the nearest boundary point and flag it (the vehicle's pose in an inflated wall)
  Refuse,  // report StartInObstacle / GoalInObstacle
};

struct PathPoint {
  geometry::Point position = geometry::Point::Zero();
  VertexId vertex = kNoVertex;                 // kNoVertex for the robot and the goal
  std::uint32_t interaction = kNoInteraction;  // set when the step INTO this point pushes an object
  std::int64_t object_id = 0;
  std::uint32_t push_plan = 0;
};

struct SearchResult {
  SearchStatus status = SearchStatus::NoPath;
  std::vector<PathPoint> path;                      // robot first, goal last (when Found)
  double cost = 0.0;                                // sum of edge costs: length, J, any surcharge
  double length = 0.0;                              // geometric length
  geometry::Point start = geometry::Point::Zero();  // after snapping (as given when refused)
  geometry::Point goal = geometry::Point::Zero();
  bool start_snapped =
      false;  // was inside an obstacle, moved to the nearest free point (InsideObstacle::Snap)
  bool goal_snapped = false;
  std::size_t expansions = 0;
  std::size_t start_links = 0;  // vertices found to see the robot (tested lazily, in priority order)
  std::size_t goal_links = 0;   // expanded vertices found to see the goal (tested lazily)
  std::size_t start_tests = 0;  // lines from the robot tested for visibility (tangent vertices only)
  std::size_t goal_tests = 0;   // lines to the goal tested for visibility
  /// With NoPath: of the vertices the search reached, the one nearest the goal (straight line) and how
  /// far it is from it; infinity when it reached none.
  geometry::Point nearest_reached = geometry::Point::Zero();
  double nearest_reached_distance = std::numeric_limits<double>::infinity();
};

/// Why `result` found no path, in words for a status line: nothing visible from the start (it is
/// enclosed), or how many vertices were reached and where the nearest of them to the goal is (where the
/// graph stops short of it). Empty when the status is not NoPath.
std::string describeNoPath(const SearchResult& result);

/// The route the previous search chose, kept when a new one is not clearly better: its arcs cost
/// `discount` (a fraction) less, and all of them together at most `cap_m` less, taken from its first
/// arcs on. Without it the route flips between two ways of nearly equal length as each frame moves a
/// vertex a little, and the vehicle turns back and forth between them.
struct RoutePreference {
  std::vector<VertexId> route;  // graph vertices in path order; ids no longer in the graph are skipped
  double discount = 0.0;        // 0 .. 0.9 (larger values count as 0.9)
  double cap_m = 0.0;           // metres; <= 0: no cap (a fraction of the whole route)
};

/// A price on a stretch of way on top of its length, in metres (e.g. for the part of it nobody has seen).
/// Empty: none. Never negative, so the Euclidean heuristic stays admissible.
using WaySurcharge = std::function<double(const geometry::Point& from, const geometry::Point& to)>;

/// Search state, reusable across searches of any graph; not shared between threads.
class SearchScratch {
 private:
  friend class AStarSearch;
  struct QueueEntry {
    double priority;
    std::uint32_t vertex;
  };
  struct VertexState {  // together: one cache line per visited vertex
    double cost = 0.0;
    double heuristic = 0.0;    // distance to the goal, computed when first seen
    std::uint32_t seen = 0;    // generation in which `cost` and `heuristic` were set
    std::uint32_t closed = 0;  // generation in which the vertex was expanded
  };
  std::vector<VertexState> states_;
  std::vector<std::uint32_t> parent_;
  // The flood over the vertex grid that orders the robot's links (cell index in QueueEntry::vertex).
  std::vector<QueueEntry> cell_queue_;
  std::vector<double> cell_key_;
  std::vector<std::uint32_t> cell_seen_stamp_;
  std::vector<std::uint32_t> cell_done_stamp_;
  std::vector<QueueEntry> queue_;
  std::vector<std::uint32_t> preferred_next_;  // per vertex: the next vertex on the preferred route
  std::vector<double> preferred_budget_;       // per vertex: the most its preferred arc is discounted (m)
  std::uint32_t generation_ = 0;
};

class AStarSearch {
 public:
  /// Plans from `start` to `goal`. A start or goal inside an obstacle is snapped to the nearest
  /// boundary point and flagged, or refused with a status when `inside` says so; one off a bounded map or
  /// not finite is refused with a status. With a
  /// preference the result's cost is still the true one (no discount), and the path may be the preferred
  /// one where another is shorter by less than about the discount on the preferred arcs. A surcharge adds
  /// to every stretch it prices (robot links, arcs, goal links) and is part of the cost reported.
  static SearchResult run(const SearchGraph& graph, const ObstacleSet& obstacles,
                          const geometry::Point& start, const geometry::Point& goal, SearchScratch& scratch,
                          const RoutePreference& preference = {}, const WaySurcharge& surcharge = {},
                          InsideObstacle inside = InsideObstacle::Snap);

 private:
  class Query;  // one query's roles: validity, heuristic, arc costs, robot links, expansion
                // (a_star_query.hpp)
};

/// Convenience wrapper around AStarSearch::run.
inline SearchResult findPath(const SearchGraph& graph, const ObstacleSet& obstacles,
                             const geometry::Point& start, const geometry::Point& goal,
                             SearchScratch& scratch, const RoutePreference& preference = {},
                             const WaySurcharge& surcharge = {}, InsideObstacle inside = InsideObstacle::Snap)
{
  return AStarSearch::run(graph, obstacles, start, goal, scratch, preference, surcharge, inside);
}

}  // namespace ifar::graph
