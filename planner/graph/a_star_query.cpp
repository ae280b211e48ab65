#include "planner/graph/a_star_query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "planner/graph/quaternary_heap.hpp"

namespace ifar::graph {
namespace {

constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();

}  // namespace

AStarSearch::Query::Query(const SearchGraph& graph, const ObstacleSet& obstacles,
                          const geometry::Point& start, const geometry::Point& goal, SearchScratch& scratch,
                          const RoutePreference& preference, const WaySurcharge& surcharge)
    : graph_(graph),
      obstacles_(obstacles),
      start_(start),
      goal_(goal),
      scratch_(scratch),
      preference_(preference),
      surcharge_(surcharge),
      count_(graph.size()),
      start_index_(static_cast<std::uint32_t>(graph.size())),
      goal_index_(static_cast<std::uint32_t>(graph.size()) + 1),
      start_cache_(start),
      goal_cache_(goal),
      kept_fraction_(1.0 - std::clamp(preference.discount, 0.0, 0.9)),
      preferring_(kept_fraction_ < 1.0 && preference.route.size() >= 2),
      surcharged_(static_cast<bool>(surcharge)),
      // A preference or a surcharge prices a way by more than its length: a bend that a straighter way
      // would cut may then be the cheapest.
      taut_only_(!graph.taut_only_.empty() && !preferring_ && !surcharged_)
{
  startGeneration();
  prepareCells();
  seedCells();
  preparePreference();
}

void AStarSearch::Query::startGeneration()
{
  if (scratch_.states_.size() < count_ + 2) {
    scratch_.states_.resize(count_ + 2);
    scratch_.parent_.resize(count_ + 2);
  }
  if (++scratch_.generation_ == 0) {  // wrapped: clear the stamps once every 4 billion searches
    std::fill(scratch_.states_.begin(), scratch_.states_.end(), SearchScratch::VertexState{});
    std::fill(scratch_.cell_seen_stamp_.begin(), scratch_.cell_seen_stamp_.end(), 0);
    std::fill(scratch_.cell_done_stamp_.begin(), scratch_.cell_done_stamp_.end(), 0);
    scratch_.generation_ = 1;
  }
  generation_ = scratch_.generation_;
}

void AStarSearch::Query::run(SearchResult& result)
{
  scratch_.queue_.clear();
  // The robot is expanded first; its links arrive from the flood over the vertex grid.
  scratch_.states_[start_index_].seen = generation_;
  scratch_.states_[start_index_].closed = generation_;
  scratch_.states_[start_index_].cost = 0.0;
  scratch_.parent_[start_index_] = kNoIndex;
  ++result.expansions;
  bool found = false;
  while (true) {
    linkStartUpTo(result);
    if (scratch_.queue_.empty()) {
      break;
    }
    const SearchScratch::QueueEntry entry = popQuaternary(scratch_.queue_);
    const std::uint32_t vertex = entry.vertex;
    if (scratch_.states_[vertex].closed == generation_) {
      continue;
    }
    scratch_.states_[vertex].closed = generation_;
    ++result.expansions;
    if (vertex == goal_index_) {
      found = true;
      break;
    }
    // The heuristic is the straight-line distance to the goal: where a failed search got nearest.
    if (scratch_.states_[vertex].heuristic < result.nearest_reached_distance) {
      result.nearest_reached_distance = scratch_.states_[vertex].heuristic;
      result.nearest_reached = graph_.positions_[vertex];
    }
    expand(vertex, result);
  }
  if (!found) {
    result.status = SearchStatus::NoPath;
    return;
  }
  result.status = SearchStatus::Found;
  result.cost = scratch_.states_[goal_index_].cost;
  readPath(result);
}

inline bool AStarSearch::Query::seesStart(std::uint32_t vertex, SearchResult& result)
{
  const geometry::Point& position = graph_.positions_[vertex];
  const bool corner = graph_.kinds_[vertex] == VertexKind::Corner;
  const LoopCorner geometry{position, graph_.previous_[vertex], graph_.next_[vertex], 0};
  if (corner && !isTangent(geometry, position - start_)) {
    return false;
  }
  ++result.start_tests;
  return obstacles_.visibleFrom(position, start_cache_);
}

inline bool AStarSearch::Query::seesGoal(std::uint32_t vertex, SearchResult& result)
{
  const geometry::Point& position = graph_.positions_[vertex];
  const bool corner = graph_.kinds_[vertex] == VertexKind::Corner;
  const LoopCorner geometry{position, graph_.previous_[vertex], graph_.next_[vertex], 0};
  if (corner && !isTangent(geometry, position - goal_)) {
    return false;
  }
  ++result.goal_tests;
  return obstacles_.visibleFrom(position, goal_cache_);
}

void AStarSearch::Query::preparePreference()
{
  // The preferred route's arcs, as "next vertex" per vertex (a route passes each vertex once). Their
  // discount makes the heuristic inconsistent there, so a closed vertex may not be final and the path
  // may be a little longer than the best under the discount; it is still a valid path, at its true cost.
  if (!preferring_) {
    return;
  }
  scratch_.preferred_next_.assign(count_, kNoIndex);
  scratch_.preferred_budget_.assign(count_, 0.0);
  const auto indexOf = [&](VertexId id) {
    return id < graph_.index_of_.size() ? graph_.index_of_[id] : kNoIndex;
  };
  // The cap is shared out along the route from its start: the arcs the vehicle takes next keep the
  // route, a way that is shorter by more than the cap replaces it however long the route.
  const bool capped = preference_.cap_m > 0.0;
  double budget_left = preference_.cap_m;
  const double fraction = 1.0 - kept_fraction_;
  for (std::size_t step = 1; step < preference_.route.size(); ++step) {
    const std::uint32_t from = indexOf(preference_.route[step - 1]);
    const std::uint32_t to = indexOf(preference_.route[step]);
    if (from == kNoIndex || to == kNoIndex) {
      continue;
    }
    scratch_.preferred_next_[from] = to;
    if (capped) {
      const double budget =
          std::min(fraction * (graph_.positions_[to] - graph_.positions_[from]).norm(), budget_left);
      scratch_.preferred_budget_[from] = budget;
      budget_left -= budget;
    } else {
      scratch_.preferred_budget_[from] = std::numeric_limits<double>::infinity();
    }
  }
}

inline double AStarSearch::Query::arcCost(std::uint32_t from, std::uint32_t arc) const
{
  const std::uint32_t to = graph_.targets_[arc];
  double cost = graph_.costs_[arc];
  if (surcharged_) {
    cost += surchargeOf(graph_.positions_[from], graph_.positions_[to]);
  }
  if (!preferred(from, to)) {
    return cost;
  }
  return cost - std::min(cost * (1.0 - kept_fraction_), scratch_.preferred_budget_[from]);
}

double AStarSearch::Query::startArcCost(std::uint32_t from, std::uint32_t arc) const
{
  // A push whose start waypoint the robot links to directly, with the robot nearer the push's contact
  // than the waypoint is (on its way to the contact, or at the object when a push is replanned), starts
  // where the robot is: the way back to the waypoint and the approach from it are not paid. Without this a
  // push under way cost about twice the waypoint offset more than every other way at each replan.
  const double cost = arcCost(from, arc);
  const std::uint32_t interaction = graph_.interactionOf(arc);
  if (interaction == kNoInteraction) {
    return cost;
  }
  const double approach = graph_.interaction_approaches_[interaction];
  const geometry::Point& contact = graph_.interaction_contacts_[interaction];
  const double to_contact = (contact - start_).norm();
  if (!(approach > 0.0) || to_contact > approach || !obstacles_.visible(start_, contact)) {
    return cost;
  }
  const double to_waypoint = (graph_.positions_[from] - start_).norm();
  const double straight = (graph_.positions_[graph_.targets_[arc]] - start_).norm() - to_waypoint;
  return std::max({cost - (to_waypoint + approach - to_contact), straight, 0.0});
}

void AStarSearch::Query::prepareCells()
{
  // The robot's links are attached lazily too. A link to vertex v can only matter once A* reaches the
  // priority f(v) = |v - start| + h(v). Every point x on the segment from the robot to v has
  // |x - start| + |x - goal| <= f(v), so the cells of the vertex grid that segment crosses all have a lower
  // bound of that sum (over the cell's box) of at most f(v). The cells are therefore flooded from the
  // robot's cell in order of the largest such bound along the way, and a cell's vertices are tested
  // (tangency, then visibility) before A* expands anything of higher priority. Every link that can
  // influence the result is in place in time, so the search is the same as with every visible vertex
  // linked up front, while a short query only looks at the cells around its straight line.
  cell_count_ = graph_.cell_offsets_.empty() ? 0 : graph_.cell_offsets_.size() - 1;
  if (scratch_.cell_key_.size() < cell_count_) {
    scratch_.cell_key_.resize(cell_count_);
    scratch_.cell_seen_stamp_.resize(cell_count_, 0);
    scratch_.cell_done_stamp_.resize(cell_count_, 0);
  }
  scratch_.cell_queue_.clear();
}

inline double AStarSearch::Query::cellBound(int column, int row) const
{
  const geometry::Point low =
      graph_.cell_origin_ +
      graph_.cell_size_ * geometry::Point(static_cast<double>(column), static_cast<double>(row));
  const geometry::Point high = low + geometry::Point(graph_.cell_size_, graph_.cell_size_);
  const auto distance = [&](const geometry::Point& point) {
    return (low - point).cwiseMax(point - high).cwiseMax(0.0).norm();
  };
  return distance(start_) + distance(goal_);
}

inline void AStarSearch::Query::offerCell(int column, int row, double reached)
{
  const std::size_t cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(graph_.cell_columns_) +
                           static_cast<std::size_t>(column);
  if (scratch_.cell_done_stamp_[cell] == generation_) {
    return;
  }
  const double key = std::max(reached, cellBound(column, row));
  if (scratch_.cell_seen_stamp_[cell] == generation_ && key >= scratch_.cell_key_[cell]) {
    return;
  }
  scratch_.cell_seen_stamp_[cell] = generation_;
  scratch_.cell_key_[cell] = key;
  scratch_.cell_queue_.push_back({key, static_cast<std::uint32_t>(cell)});
  std::push_heap(scratch_.cell_queue_.begin(), scratch_.cell_queue_.end(), LaterFirst{});
}

void AStarSearch::Query::seedCells()
{
  if (cell_count_ == 0) {
    return;
  }
  const geometry::Point relative = (start_ - graph_.cell_origin_) / graph_.cell_size_;
  if (relative.x() >= 0.0 && relative.y() >= 0.0 && relative.x() < graph_.cell_columns_ &&
      relative.y() < graph_.cell_rows_) {
    offerCell(static_cast<int>(relative.x()), static_cast<int>(relative.y()), 0.0);
    return;
  }
  // Outside the grid: the segment to any vertex enters through a border cell.
  for (int column = 0; column < graph_.cell_columns_; ++column) {
    offerCell(column, 0, 0.0);
    offerCell(column, graph_.cell_rows_ - 1, 0.0);
  }
  for (int row = 0; row < graph_.cell_rows_; ++row) {
    offerCell(0, row, 0.0);
    offerCell(graph_.cell_columns_ - 1, row, 0.0);
  }
}

inline void AStarSearch::Query::linkStartUpTo(SearchResult& result)
{
  auto& cells = scratch_.cell_queue_;
  const auto& queue = scratch_.queue_;
  while (!cells.empty() && (queue.empty() || cells.front().priority <= queue.front().priority)) {
    std::pop_heap(cells.begin(), cells.end(), LaterFirst{});
    const SearchScratch::QueueEntry cell_entry = cells.back();
    cells.pop_back();
    linkCell(cell_entry, result);
  }
}

inline void AStarSearch::Query::linkCell(const SearchScratch::QueueEntry& cell_entry, SearchResult& result)
{
  const std::uint32_t cell = cell_entry.vertex;
  if (scratch_.cell_done_stamp_[cell] == generation_) {
    return;
  }
  scratch_.cell_done_stamp_[cell] = generation_;
  for (std::uint32_t slot = graph_.cell_offsets_[cell]; slot < graph_.cell_offsets_[cell + 1]; ++slot) {
    const std::uint32_t vertex = graph_.cell_vertices_[slot];
    if (seesStart(vertex, result)) {
      ++result.start_links;
      relax(start_index_, vertex,
            (graph_.positions_[vertex] - start_).norm() + surchargeOf(start_, graph_.positions_[vertex]));
    }
  }
  const int column = static_cast<int>(cell % static_cast<std::uint32_t>(graph_.cell_columns_));
  const int row = static_cast<int>(cell / static_cast<std::uint32_t>(graph_.cell_columns_));
  if (column > 0) {
    offerCell(column - 1, row, cell_entry.priority);
  }
  if (column + 1 < graph_.cell_columns_) {
    offerCell(column + 1, row, cell_entry.priority);
  }
  if (row > 0) {
    offerCell(column, row - 1, cell_entry.priority);
  }
  if (row + 1 < graph_.cell_rows_) {
    offerCell(column, row + 1, cell_entry.priority);
  }
}

inline void AStarSearch::Query::relax(std::uint32_t from, std::uint32_t to, double cost)
{
  const double candidate = scratch_.states_[from].cost + cost;
  SearchScratch::VertexState& state = scratch_.states_[to];
  if (state.seen == generation_) {
    if (candidate >= state.cost || state.closed == generation_) {
      return;  // no better, or final (consistent heuristic: closed vertices are final)
    }
  } else {
    state.seen = generation_;
    state.heuristic = to == goal_index_ ? 0.0 : heuristic(to);
  }
  state.cost = candidate;
  scratch_.parent_[to] = from;
  pushQuaternary(scratch_.queue_, SearchScratch::QueueEntry{candidate + state.heuristic, to});
}

inline void AStarSearch::Query::expand(std::uint32_t vertex, SearchResult& result)
{
  if (taut_only_ && graph_.taut_only_[vertex] != 0) {
    expandTaut(vertex, result);
    return;
  }
  for (std::uint32_t arc = graph_.offsets_[vertex]; arc < graph_.offsets_[vertex + 1]; ++arc) {
    relax(vertex, graph_.targets_[arc], arcCost(vertex, arc));
  }
  // A vertex the robot links to straight away may start a push where the robot is: its interaction
  // arcs again at that price (relax keeps the lower). Apart from the loop above, which stays as lean as
  // it was for every other vertex.
  if (scratch_.parent_[vertex] == start_index_) {
    for (std::uint32_t arc = graph_.offsets_[vertex]; arc < graph_.offsets_[vertex + 1]; ++arc) {
      if (graph_.interactionOf(arc) != kNoInteraction) {
        relax(vertex, graph_.targets_[arc], startArcCost(vertex, arc));
      }
    }
  }
  linkGoal(vertex, result);
}

inline void AStarSearch::Query::expandTaut(std::uint32_t vertex, SearchResult& result)
{
  // Only the bends that wrap this corner (isTautBend): a path reaching it from its parent and turning
  // the other way is cut short near the corner by a free chord, so it is never the shortest. The graph
  // has no interaction arcs and the costs are lengths (no preference, no surcharge) here.
  const geometry::Point& position = graph_.positions_[vertex];
  const LoopCorner corner{position, graph_.previous_[vertex], graph_.next_[vertex], 0};
  const std::uint32_t parent = scratch_.parent_[vertex];
  const geometry::Vector incoming = position - (parent == start_index_ ? start_ : graph_.positions_[parent]);
  const int incoming_side = wedgeSide(corner, incoming);
  const std::uint32_t left_end = graph_.left_end_[vertex];
  const std::uint32_t right_end = graph_.right_end_[vertex];
  // With the wedge on the left of the way in, only a left turn (or none) with the wedge on the left of
  // the way out wraps it: the left run up to the incoming direction (search.cpp sorts it so). Mirrored
  // on the right; undecided ways in look at every arc.
  if (incoming_side > 0) {
    for (std::uint32_t arc = graph_.offsets_[vertex]; arc < left_end; ++arc) {
      const std::uint32_t to = graph_.targets_[arc];
      if (turnSide(incoming, graph_.positions_[to] - position) < 0) {
        break;
      }
      relax(vertex, to, graph_.costs_[arc]);
    }
  } else if (incoming_side < 0) {
    for (std::uint32_t arc = left_end; arc < right_end; ++arc) {
      const std::uint32_t to = graph_.targets_[arc];
      if (turnSide(incoming, graph_.positions_[to] - position) > 0) {
        break;
      }
      relax(vertex, to, graph_.costs_[arc]);
    }
  } else {
    for (std::uint32_t arc = graph_.offsets_[vertex]; arc < right_end; ++arc) {
      const std::uint32_t to = graph_.targets_[arc];
      if (isTautBend(corner, incoming, graph_.positions_[to] - position)) {
        relax(vertex, to, graph_.costs_[arc]);
      }
    }
  }
  for (std::uint32_t arc = right_end; arc < graph_.offsets_[vertex + 1]; ++arc) {
    const std::uint32_t to = graph_.targets_[arc];
    if (isTautBend(corner, incoming, graph_.positions_[to] - position)) {
      relax(vertex, to, graph_.costs_[arc]);
    }
  }
  if (isTautBend(corner, incoming, goal_ - position)) {
    linkGoal(vertex, result);
  }
}

inline void AStarSearch::Query::linkGoal(std::uint32_t vertex, SearchResult& result)
{
  // The goal is attached lazily: its link from a vertex only matters once that vertex is expanded,
  // so testing visibility here gives the same result as attaching it to every vertex up front.
  if (seesGoal(vertex, result)) {
    ++result.goal_links;
    relax(vertex, goal_index_,
          (goal_ - graph_.positions_[vertex]).norm() + surchargeOf(graph_.positions_[vertex], goal_));
  }
}

void AStarSearch::Query::readPath(SearchResult& result) const
{
  std::vector<std::uint32_t> chain;
  for (std::uint32_t vertex = goal_index_; vertex != kNoIndex; vertex = scratch_.parent_[vertex]) {
    chain.push_back(vertex);
  }
  std::reverse(chain.begin(), chain.end());
  for (std::size_t index = 0; index < chain.size(); ++index) {
    const std::uint32_t vertex = chain[index];
    PathPoint point;
    if (vertex == start_index_) {
      point.position = start_;
    } else if (vertex == goal_index_) {
      point.position = goal_;
    } else {
      point.position = graph_.positions_[vertex];
      point.vertex = graph_.ids_[vertex];
    }
    if (index > 0 && chain[index - 1] < count_ && vertex < count_) {
      const std::uint32_t from = chain[index - 1];
      const std::optional<std::uint32_t> taken = arcTaken(from, vertex);
      if (taken && graph_.interactionOf(*taken) != kNoInteraction) {
        point.interaction = graph_.interactionOf(*taken);
        point.object_id = graph_.interaction_objects_[point.interaction];
        point.push_plan = graph_.interaction_plans_[point.interaction];
      }
      if (taken && preferred(from, vertex)) {
        // Report the true cost: add back what the preference took off this step.
        result.cost += graph_.costs_[*taken] +
                       surchargeOf(graph_.positions_[from], graph_.positions_[vertex]) -
                       arcCost(from, *taken);
      }
    }
    if (!result.path.empty()) {
      result.length += (point.position - result.path.back().position).norm();
    }
    result.path.push_back(point);
  }
}

std::optional<std::uint32_t> AStarSearch::Query::arcTaken(std::uint32_t from, std::uint32_t vertex) const
{
  // The arc the search took: an interaction arc when one gave this cost, else the visibility link.
  std::optional<std::uint32_t> taken;
  const bool linked_to_robot = scratch_.parent_[from] == start_index_;
  for (std::uint32_t arc = graph_.offsets_[from]; arc < graph_.offsets_[from + 1]; ++arc) {
    if (graph_.targets_[arc] != vertex) {
      continue;  // only arcs to this vertex are costed (a surcharge walks the arc's cells)
    }
    const double cost = linked_to_robot ? startArcCost(from, arc) : arcCost(from, arc);
    if (std::abs(scratch_.states_[from].cost + cost - scratch_.states_[vertex].cost) < 1e-9 &&
        (!taken ||
         (graph_.interactionOf(*taken) == kNoInteraction && graph_.interactionOf(arc) != kNoInteraction))) {
      taken = arc;  // the first interaction arc that gives the cost, else the first arc that does
    }
  }
  return taken;
}

}  // namespace ifar::graph
