#pragma once
// One A* query of AStarSearch (search.hpp), in roles: validity (which vertices the robot and the goal
// see), the heuristic, arc costs (length, surcharge, route preference, a push started where the robot
// is), the lazy robot links (a flood over the vertex grid in priority order), node expansion, the loop,
// and reading the path back. Internal to planner/graph; lives only for the duration of run().

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "common/geometry/point.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/search.hpp"

namespace ifar::graph {

class AStarSearch::Query {
 public:
  /// `start` and `goal` are finite, on the map and snapped to free space; they do not see each other.
  /// Every reference must outlive the query; `scratch` is its state.
  Query(const SearchGraph& graph, const ObstacleSet& obstacles, const geometry::Point& start,
        const geometry::Point& goal, SearchScratch& scratch, const RoutePreference& preference,
        const WaySurcharge& surcharge);
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;

  /// Runs A* and fills `result`'s status, cost, path, length, expansions and link counts.
  void run(SearchResult& result);

 private:
  // State: one generation of the scratch per query.
  void startGeneration();
  // Validity: a vertex the robot (goal) sees, and tangent to it if a corner.
  bool seesStart(std::uint32_t vertex, SearchResult& result);
  bool seesGoal(std::uint32_t vertex, SearchResult& result);
  // Heuristic: the straight line to the goal.
  double heuristic(std::uint32_t vertex) const { return (goal_ - graph_.positions_[vertex]).norm(); }
  // Arc costs.
  void preparePreference();
  bool preferred(std::uint32_t from, std::uint32_t to) const
  {
    return preferring_ && scratch_.preferred_next_[from] == to;
  }
  double surchargeOf(const geometry::Point& from, const geometry::Point& to) const
  {
    return surcharged_ ? std::max(0.0, surcharge_(from, to)) : 0.0;
  }
  double arcCost(std::uint32_t from, std::uint32_t arc) const;
  double startArcCost(std::uint32_t from, std::uint32_t arc) const;
  // The robot's links, lazily in priority order.
  /// Orders the cell flood's std heap by lowest priority first (a function object, so the heap
  /// operations inline it).
  struct LaterFirst {
    bool operator()(const SearchScratch::QueueEntry& a, const SearchScratch::QueueEntry& b) const
    {
      return a.priority > b.priority;
    }
  };
  void prepareCells();
  double cellBound(int column, int row) const;
  void offerCell(int column, int row, double reached);
  void seedCells();
  void linkStartUpTo(SearchResult& result);
  void linkCell(const SearchScratch::QueueEntry& cell_entry, SearchResult& result);
  // Expansion.
  void relax(std::uint32_t from, std::uint32_t to, double cost);
  void expand(std::uint32_t vertex, SearchResult& result);
  void expandTaut(std::uint32_t vertex, SearchResult& result);
  void linkGoal(std::uint32_t vertex, SearchResult& result);
  // The path.
  void readPath(SearchResult& result) const;
  std::optional<std::uint32_t> arcTaken(std::uint32_t from, std::uint32_t vertex) const;

  const SearchGraph& graph_;
  const ObstacleSet& obstacles_;
  geometry::Point start_;
  geometry::Point goal_;
  SearchScratch& scratch_;
  const RoutePreference& preference_;
  const WaySurcharge& surcharge_;
  std::size_t count_ = 0;  ///< graph vertices; the robot and the goal follow them
  std::uint32_t start_index_ = 0;
  std::uint32_t goal_index_ = 0;
  std::uint32_t generation_ = 0;
  std::size_t cell_count_ = 0;
  SectorBlockerCache start_cache_;
  SectorBlockerCache goal_cache_;
  double kept_fraction_ = 1.0;  ///< of a preferred arc's cost
  bool preferring_ = false;
  bool surcharged_ = false;
  bool taut_only_ = false;  ///< bends away from a corner are skipped (SearchGraph::fromCompleteGraph)
};

}  // namespace ifar::graph
