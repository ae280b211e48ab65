#include "planner/graph/search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ifar::graph {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Vertices per cell of the grid that orders the robot's links (see AStarSearch::run), on average.
constexpr double kVerticesPerCell = 6.0;

/// A 4-ary min-heap on `priority` over a vector: half the levels of a binary heap, and the four children
/// of a node share a cache line.
template <typename Entry>
void pushQuaternary(std::vector<Entry>& heap, const Entry& entry)
{
  std::size_t index = heap.size();
  heap.push_back(entry);
  while (index > 0) {
    const std::size_t parent = (index - 1) / 4;
    if (!(entry.priority < heap[parent].priority)) {
      break;
    }
    heap[index] = heap[parent];
    index = parent;
  }
  heap[index] = entry;
}

template <typename Entry>
Entry popQuaternary(std::vector<Entry>& heap)
{
  const Entry top = heap.front();
  const Entry last = heap.back();
  heap.pop_back();
  const std::size_t size = heap.size();
  if (size == 0) {
    return top;
  }
  std::size_t index = 0;
  while (true) {
    const std::size_t first = 4 * index + 1;
    if (first >= size) {
      break;
    }
    std::size_t best = first;
    const std::size_t end = std::min(first + 4, size);
    for (std::size_t child = first + 1; child < end; ++child) {
      if (heap[child].priority < heap[best].priority) {
        best = child;
      }
    }
    if (!(heap[best].priority < last.priority)) {
      break;
    }
    heap[index] = heap[best];
    index = best;
  }
  heap[index] = last;
  return top;
}

}  // namespace

const char* toString(SearchStatus status)
{
  switch (status) {
    case SearchStatus::Found:
      return "found";
    case SearchStatus::NoPath:
      return "no_path";
    case SearchStatus::InvalidStart:
      return "invalid_start";
    case SearchStatus::InvalidGoal:
      return "invalid_goal";
    case SearchStatus::StartOffMap:
      return "start_off_map";
    case SearchStatus::GoalOffMap:
      return "goal_off_map";
  }
  return "unknown";
}

SearchGraph SearchGraph::fromDvGraph(const DvGraph& graph)
{
  SearchGraph result;
  const auto& slots = graph.vertexSlots();
  std::vector<std::uint32_t> dense(slots.size(), kNone);
  for (const auto& vertex : slots) {
    if (!vertex.alive) {
      continue;
    }
    dense[vertex.id] = static_cast<std::uint32_t>(result.ids_.size());
    result.ids_.push_back(vertex.id);
    result.positions_.push_back(vertex.position);
    result.previous_.push_back(vertex.previous);
    result.next_.push_back(vertex.next);
    result.kinds_.push_back(vertex.kind);
  }
  result.buildVertexGrid();
  // Interaction edges grouped by their tail vertex.
  std::vector<std::vector<std::uint32_t>> outgoing(result.ids_.size());
  const auto& interactions = graph.interactionEdges();
  for (std::uint32_t index = 0; index < interactions.size(); ++index) {
    const auto& edge = interactions[index];
    if (edge.alive && graph.contains(edge.from) && graph.contains(edge.to)) {
      outgoing[dense[edge.from]].push_back(index);
    }
  }
  result.offsets_.reserve(result.ids_.size() + 1);
  result.offsets_.push_back(0);
  for (std::size_t local = 0; local < result.ids_.size(); ++local) {
    for (const auto& link : graph.visibilityLinks(result.ids_[local])) {
      result.targets_.push_back(dense[link.other]);
      result.costs_.push_back(link.length);
      result.interaction_.push_back(kNoInteraction);
    }
    for (const std::uint32_t index : outgoing[local]) {
      const auto& edge = interactions[index];
      const double length = (graph.vertex(edge.to)->position - graph.vertex(edge.from)->position).norm();
      result.targets_.push_back(dense[edge.to]);
      // J is the whole price of the push; the travel along the edge is part of it, never below it.
      result.costs_.push_back(std::max(edge.cost, length));
      result.interaction_.push_back(index);
    }
    result.offsets_.push_back(static_cast<std::uint32_t>(result.targets_.size()));
  }
  for (const auto& edge : interactions) {
    result.interaction_objects_.push_back(edge.object_id);
    result.interaction_plans_.push_back(edge.push_plan);
    result.interaction_contacts_.push_back(edge.contact);
    result.interaction_approaches_.push_back(edge.approach_m);
  }
  result.index_of_ = std::move(dense);
  return result;
}

void SearchGraph::buildVertexGrid()
{
  cell_offsets_.clear();
  cell_vertices_.clear();
  cell_columns_ = cell_rows_ = 0;
  geometry::Point low = geometry::Point::Constant(std::numeric_limits<double>::infinity());
  geometry::Point high = -low;
  for (const geometry::Point& position : positions_) {
    if (position.allFinite()) {
      low = low.cwiseMin(position);
      high = high.cwiseMax(position);
    }
  }
  if (!(low.x() <= high.x())) {
    return;  // no vertex with finite coordinates: nothing to attach
  }
  const geometry::Point extent = (high - low).cwiseMax(geometry::Point(1e-9, 1e-9));
  const double cells_wanted = std::max(1.0, static_cast<double>(positions_.size()) / kVerticesPerCell);
  cell_size_ = std::max(std::sqrt(extent.x() * extent.y() / cells_wanted), extent.maxCoeff() / 512.0);
  cell_origin_ = low;
  cell_columns_ = static_cast<int>(std::floor(extent.x() / cell_size_)) + 1;
  cell_rows_ = static_cast<int>(std::floor(extent.y() / cell_size_)) + 1;
  const auto cellOf = [&](const geometry::Point& position) -> std::size_t {
    if (!position.allFinite()) {
      return 0;  // never visible from anywhere; any cell will do
    }
    const geometry::Point relative = (position - cell_origin_) / cell_size_;
    const int column = std::clamp(static_cast<int>(std::floor(relative.x())), 0, cell_columns_ - 1);
    const int row = std::clamp(static_cast<int>(std::floor(relative.y())), 0, cell_rows_ - 1);
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cell_columns_) +
           static_cast<std::size_t>(column);
  };
  // Counting sort: vertices grouped by cell, index order inside a cell.
  cell_offsets_.assign(static_cast<std::size_t>(cell_columns_) * static_cast<std::size_t>(cell_rows_) + 1, 0);
  for (const geometry::Point& position : positions_) {
    ++cell_offsets_[cellOf(position) + 1];
  }
  for (std::size_t cell = 1; cell < cell_offsets_.size(); ++cell) {
    cell_offsets_[cell] += cell_offsets_[cell - 1];
  }
  std::vector<std::uint32_t> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
  cell_vertices_.resize(positions_.size());
  for (std::uint32_t vertex = 0; vertex < positions_.size(); ++vertex) {
    cell_vertices_[fill[cellOf(positions_[vertex])]++] = vertex;
  }
}

SearchResult AStarSearch::run(const SearchGraph& graph, const ObstacleSet& obstacles,
                              const geometry::Point& start_in, const geometry::Point& goal_in,
                              SearchScratch& scratch, const RoutePreference& preference,
                              const WaySurcharge& surcharge)
{
  SearchResult result;
  if (!start_in.allFinite()) {
    result.status = SearchStatus::InvalidStart;
    return result;
  }
  if (!goal_in.allFinite()) {
    result.status = SearchStatus::InvalidGoal;
    return result;
  }
  const auto& bounds = obstacles.bounds();
  if (bounds && !bounds->contains(start_in)) {
    result.status = SearchStatus::StartOffMap;
    return result;
  }
  if (bounds && !bounds->contains(goal_in)) {
    result.status = SearchStatus::GoalOffMap;
    return result;
  }
  const SnapResult start_snap = obstacles.snapToFree(start_in);
  const SnapResult goal_snap = obstacles.snapToFree(goal_in);
  const geometry::Point start = start_snap.point;
  const geometry::Point goal = goal_snap.point;
  result.start = start;
  result.goal = goal;
  result.start_snapped = start_snap.snapped;
  result.goal_snapped = goal_snap.snapped;

  if (obstacles.visible(start, goal)) {
    result.status = SearchStatus::Found;
    result.path = {PathPoint{start}, PathPoint{goal}};
    result.length = result.cost = (goal - start).norm();
    return result;
  }

  const std::size_t count = graph.size();
  const std::uint32_t start_index = static_cast<std::uint32_t>(count);
  const std::uint32_t goal_index = start_index + 1;
  if (scratch.states_.size() < count + 2) {
    scratch.states_.resize(count + 2);
    scratch.parent_.resize(count + 2);
  }
  if (++scratch.generation_ == 0) {  // wrapped: clear the stamps once every 4 billion searches
    std::fill(scratch.states_.begin(), scratch.states_.end(), SearchScratch::VertexState{});
    std::fill(scratch.cell_seen_stamp_.begin(), scratch.cell_seen_stamp_.end(), 0);
    std::fill(scratch.cell_done_stamp_.begin(), scratch.cell_done_stamp_.end(), 0);
    scratch.generation_ = 1;
  }
  const std::uint32_t generation = scratch.generation_;

  const auto later = [](const SearchScratch::QueueEntry& a, const SearchScratch::QueueEntry& b) {
    return a.priority > b.priority;
  };

  // The robot's links are attached lazily too. A link to vertex v can only matter once A* reaches the
  // priority f(v) = |v - start| + h(v). Every point x on the segment from the robot to v has
  // |x - start| + |x - goal| <= f(v), so the cells of the vertex grid that segment crosses all have a lower
  // bound of that sum (over the cell's box) of at most f(v). The cells are therefore flooded from the
  // robot's cell in order of the largest such bound along the way, and a cell's vertices are tested
  // (tangency, then visibility) before A* expands anything of higher priority. Every link that can
  // influence the result is in place in time, so the search is the same as with every visible vertex
  // linked up front, while a short query only looks at the cells around its straight line.
  const std::size_t cell_count = graph.cell_offsets_.empty() ? 0 : graph.cell_offsets_.size() - 1;
  if (scratch.cell_key_.size() < cell_count) {
    scratch.cell_key_.resize(cell_count);
    scratch.cell_seen_stamp_.resize(cell_count, 0);
    scratch.cell_done_stamp_.resize(cell_count, 0);
  }
  auto& cells = scratch.cell_queue_;
  cells.clear();
  const auto cellBound = [&](int column, int row) {
    const geometry::Point low =
        graph.cell_origin_ +
        graph.cell_size_ * geometry::Point(static_cast<double>(column), static_cast<double>(row));
    const geometry::Point high = low + geometry::Point(graph.cell_size_, graph.cell_size_);
    const auto distance = [&](const geometry::Point& point) {
      return (low - point).cwiseMax(point - high).cwiseMax(0.0).norm();
    };
    return distance(start) + distance(goal);
  };
  const auto offerCell = [&](int column, int row, double reached) {
    const std::size_t cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(graph.cell_columns_) +
                             static_cast<std::size_t>(column);
    if (scratch.cell_done_stamp_[cell] == generation) {
      return;
    }
    const double key = std::max(reached, cellBound(column, row));
    if (scratch.cell_seen_stamp_[cell] == generation && key >= scratch.cell_key_[cell]) {
      return;
    }
    scratch.cell_seen_stamp_[cell] = generation;
    scratch.cell_key_[cell] = key;
    cells.push_back({key, static_cast<std::uint32_t>(cell)});
    std::push_heap(cells.begin(), cells.end(), later);
  };
  if (cell_count > 0) {
    const geometry::Point relative = (start - graph.cell_origin_) / graph.cell_size_;
    if (relative.x() >= 0.0 && relative.y() >= 0.0 && relative.x() < graph.cell_columns_ &&
        relative.y() < graph.cell_rows_) {
      offerCell(static_cast<int>(relative.x()), static_cast<int>(relative.y()), 0.0);
    } else {  // outside the grid: the segment to any vertex enters through a border cell
      for (int column = 0; column < graph.cell_columns_; ++column) {
        offerCell(column, 0, 0.0);
        offerCell(column, graph.cell_rows_ - 1, 0.0);
      }
      for (int row = 0; row < graph.cell_rows_; ++row) {
        offerCell(0, row, 0.0);
        offerCell(graph.cell_columns_ - 1, row, 0.0);
      }
    }
  }
  SectorBlockerCache start_cache(start);
  SectorBlockerCache goal_cache(goal);
  const auto seesStart = [&](std::uint32_t vertex) {
    const geometry::Point& position = graph.positions_[vertex];
    const bool corner = graph.kinds_[vertex] == VertexKind::Corner;
    const LoopCorner geometry{position, graph.previous_[vertex], graph.next_[vertex], 0};
    return (!corner || isTangent(geometry, position - start)) && obstacles.visibleFrom(position, start_cache);
  };

  const auto seesGoal = [&](std::uint32_t vertex) {
    const geometry::Point& position = graph.positions_[vertex];
    const bool corner = graph.kinds_[vertex] == VertexKind::Corner;
    const LoopCorner geometry{position, graph.previous_[vertex], graph.next_[vertex], 0};
    return (!corner || isTangent(geometry, position - goal)) && obstacles.visibleFrom(position, goal_cache);
  };
  const auto heuristic = [&](std::uint32_t vertex) { return (goal - graph.positions_[vertex]).norm(); };
  // The preferred route's arcs, as "next vertex" per vertex (a route passes each vertex once). Their
  // discount makes the heuristic inconsistent there, so a closed vertex may not be final and the path
  // may be a little longer than the best under the discount; it is still a valid path, at its true cost.
  const double kept_fraction = 1.0 - std::clamp(preference.discount, 0.0, 0.9);
  const bool preferring = kept_fraction < 1.0 && preference.route.size() >= 2;
  if (preferring) {
    scratch.preferred_next_.assign(count, kNone);
    scratch.preferred_budget_.assign(count, 0.0);
    const auto indexOf = [&](VertexId id) {
      return id < graph.index_of_.size() ? graph.index_of_[id] : kNone;
    };
    // The cap is shared out along the route from its start: the arcs the vehicle takes next keep the
    // route, a way that is shorter by more than the cap replaces it however long the route.
    const bool capped = preference.cap_m > 0.0;
    double budget_left = preference.cap_m;
    const double fraction = 1.0 - kept_fraction;
    for (std::size_t step = 1; step < preference.route.size(); ++step) {
      const std::uint32_t from = indexOf(preference.route[step - 1]);
      const std::uint32_t to = indexOf(preference.route[step]);
      if (from != kNone && to != kNone) {
        scratch.preferred_next_[from] = to;
        if (capped) {
          const double budget =
              std::min(fraction * (graph.positions_[to] - graph.positions_[from]).norm(), budget_left);
          scratch.preferred_budget_[from] = budget;
          budget_left -= budget;
        } else {
          scratch.preferred_budget_[from] = std::numeric_limits<double>::infinity();
        }
      }
    }
  }
  const auto preferred = [&](std::uint32_t from, std::uint32_t to) {
    return preferring && scratch.preferred_next_[from] == to;
  };
  const bool surcharged = static_cast<bool>(surcharge);
  const auto surchargeOf = [&](const geometry::Point& from, const geometry::Point& to) {
    return surcharged ? std::max(0.0, surcharge(from, to)) : 0.0;
  };
  const auto arcCost = [&](std::uint32_t from, std::uint32_t arc) {
    const std::uint32_t to = graph.targets_[arc];
    double cost = graph.costs_[arc];
    if (surcharged) {
      cost += surchargeOf(graph.positions_[from], graph.positions_[to]);
    }
    if (!preferred(from, to)) {
      return cost;
    }
    return cost - std::min(cost * (1.0 - kept_fraction), scratch.preferred_budget_[from]);
  };
  // A push whose start waypoint the robot links to directly, with the robot nearer the push's contact
  // than the waypoint is (on its way to the contact, or at the object when a push is replanned), starts
  // where the robot is: the way back to the waypoint and the approach from it are not paid. Without this a
  // push under way cost about twice the waypoint offset more than every other way at each replan.
  // For arcs of a vertex the robot links to straight away (its parent is the start).
  const auto startArcCost = [&](std::uint32_t from, std::uint32_t arc) {
    const double cost = arcCost(from, arc);
    const std::uint32_t interaction = graph.interaction_[arc];
    if (interaction == kNoInteraction) {
      return cost;
    }
    const double approach = graph.interaction_approaches_[interaction];
    const geometry::Point& contact = graph.interaction_contacts_[interaction];
    const double to_contact = (contact - start).norm();
    if (!(approach > 0.0) || to_contact > approach || !obstacles.visible(start, contact)) {
      return cost;
    }
    const double to_waypoint = (graph.positions_[from] - start).norm();
    const double straight = (graph.positions_[graph.targets_[arc]] - start).norm() - to_waypoint;
    return std::max({cost - (to_waypoint + approach - to_contact), straight, 0.0});
  };
  auto& queue = scratch.queue_;
  queue.clear();
  const auto relax = [&](std::uint32_t from, std::uint32_t to, double cost) {
    const double candidate = scratch.states_[from].cost + cost;
    SearchScratch::VertexState& state = scratch.states_[to];
    if (state.seen == generation) {
      if (candidate >= state.cost || state.closed == generation) {
        return;  // no better, or final (consistent heuristic: closed vertices are final)
      }
    } else {
      state.seen = generation;
      state.heuristic = to == goal_index ? 0.0 : heuristic(to);
    }
    state.cost = candidate;
    scratch.parent_[to] = from;
    pushQuaternary(queue, SearchScratch::QueueEntry{candidate + state.heuristic, to});
  };
  // The robot is expanded first; its links arrive from the flood over the vertex grid.
  scratch.states_[start_index].seen = generation;
  scratch.states_[start_index].closed = generation;
  scratch.states_[start_index].cost = 0.0;
  scratch.parent_[start_index] = kNone;
  ++result.expansions;
  bool found = false;
  while (true) {
    while (!cells.empty() && (queue.empty() || cells.front().priority <= queue.front().priority)) {
      std::pop_heap(cells.begin(), cells.end(), later);
      const SearchScratch::QueueEntry cell_entry = cells.back();
      cells.pop_back();
      const std::uint32_t cell = cell_entry.vertex;
      if (scratch.cell_done_stamp_[cell] == generation) {
        continue;
      }
      scratch.cell_done_stamp_[cell] = generation;
      for (std::uint32_t slot = graph.cell_offsets_[cell]; slot < graph.cell_offsets_[cell + 1]; ++slot) {
        const std::uint32_t vertex = graph.cell_vertices_[slot];
        if (seesStart(vertex)) {
          ++result.start_links;
          relax(start_index, vertex,
                (graph.positions_[vertex] - start).norm() + surchargeOf(start, graph.positions_[vertex]));
        }
      }
      const int column = static_cast<int>(cell % static_cast<std::uint32_t>(graph.cell_columns_));
      const int row = static_cast<int>(cell / static_cast<std::uint32_t>(graph.cell_columns_));
      if (column > 0) {
        offerCell(column - 1, row, cell_entry.priority);
      }
      if (column + 1 < graph.cell_columns_) {
        offerCell(column + 1, row, cell_entry.priority);
      }
      if (row > 0) {
        offerCell(column, row - 1, cell_entry.priority);
      }
      if (row + 1 < graph.cell_rows_) {
        offerCell(column, row + 1, cell_entry.priority);
      }
    }
    if (queue.empty()) {
      break;
    }
    const SearchScratch::QueueEntry entry = popQuaternary(queue);
    const std::uint32_t vertex = entry.vertex;
    if (scratch.states_[vertex].closed == generation) {
      continue;
    }
    scratch.states_[vertex].closed = generation;
    ++result.expansions;
    if (vertex == goal_index) {
      found = true;
      break;
    }
    for (std::uint32_t arc = graph.offsets_[vertex]; arc < graph.offsets_[vertex + 1]; ++arc) {
      relax(vertex, graph.targets_[arc], arcCost(vertex, arc));
    }
    // A vertex the robot links to straight away may start a push where the robot is: its interaction
    // arcs again at that price (relax keeps the lower). Apart from the loop above, which stays as lean as
    // it was for every other vertex.
    if (scratch.parent_[vertex] == start_index) {
      for (std::uint32_t arc = graph.offsets_[vertex]; arc < graph.offsets_[vertex + 1]; ++arc) {
        if (graph.interaction_[arc] != kNoInteraction) {
          relax(vertex, graph.targets_[arc], startArcCost(vertex, arc));
        }
      }
    }
    // The goal is attached lazily: its link from a vertex only matters once that vertex is expanded,
    // so testing visibility here gives the same result as attaching it to every vertex up front.
    if (seesGoal(vertex)) {
      ++result.goal_links;
      relax(vertex, goal_index,
            (goal - graph.positions_[vertex]).norm() + surchargeOf(graph.positions_[vertex], goal));
    }
  }
  if (!found) {
    result.status = SearchStatus::NoPath;
    return result;
  }
  result.status = SearchStatus::Found;
  result.cost = scratch.states_[goal_index].cost;
  std::vector<std::uint32_t> chain;
  for (std::uint32_t vertex = goal_index; vertex != kNone; vertex = scratch.parent_[vertex]) {
    chain.push_back(vertex);
  }
  std::reverse(chain.begin(), chain.end());
  for (std::size_t index = 0; index < chain.size(); ++index) {
    const std::uint32_t vertex = chain[index];
    PathPoint point;
    if (vertex == start_index) {
      point.position = start;
    } else if (vertex == goal_index) {
      point.position = goal;
    } else {
      point.position = graph.positions_[vertex];
      point.vertex = graph.ids_[vertex];
    }
    if (index > 0 && chain[index - 1] < count && vertex < count) {
      // The arc the search took: an interaction arc when one gave this cost, else the visibility link.
      const std::uint32_t from = chain[index - 1];
      std::optional<std::uint32_t> taken;
      const bool linked_to_robot = scratch.parent_[from] == start_index;
      for (std::uint32_t arc = graph.offsets_[from]; arc < graph.offsets_[from + 1]; ++arc) {
        if (graph.targets_[arc] != vertex) {
          continue;  // only arcs to this vertex are costed (a surcharge walks the arc's cells)
        }
        const double cost = linked_to_robot ? startArcCost(from, arc) : arcCost(from, arc);
        if (std::abs(scratch.states_[from].cost + cost - scratch.states_[vertex].cost) < 1e-9 &&
            (!taken ||
             (graph.interaction_[*taken] == kNoInteraction && graph.interaction_[arc] != kNoInteraction))) {
          taken = arc;  // the first interaction arc that gives the cost, else the first arc that does
        }
      }
      if (taken && graph.interaction_[*taken] != kNoInteraction) {
        point.interaction = graph.interaction_[*taken];
        point.object_id = graph.interaction_objects_[point.interaction];
        point.push_plan = graph.interaction_plans_[point.interaction];
      }
      if (taken && preferred(from, vertex)) {
        // Report the true cost: add back what the preference took off this step.
        result.cost += graph.costs_[*taken] + surchargeOf(graph.positions_[from], graph.positions_[vertex]) -
                       arcCost(from, *taken);
      }
    }
    if (!result.path.empty()) {
      result.length += (point.position - result.path.back().position).norm();
    }
    result.path.push_back(point);
  }
  return result;
}

}  // namespace ifar::graph
