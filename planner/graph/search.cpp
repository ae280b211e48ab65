#include "planner/graph/search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ifar::graph {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

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
  }
  return result;
}

SearchResult AStarSearch::run(const SearchGraph& graph, const ObstacleSet& obstacles,
                              const geometry::Point& start_in, const geometry::Point& goal_in,
                              SearchScratch& scratch)
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
  if (scratch.cost_so_far_.size() < count + 2) {
    scratch.cost_so_far_.resize(count + 2);
    scratch.parent_.resize(count + 2);
    scratch.seen_stamp_.resize(count + 2, 0);
    scratch.closed_stamp_.resize(count + 2, 0);
  }
  if (++scratch.generation_ == 0) {  // wrapped: clear the stamps once every 4 billion searches
    std::fill(scratch.seen_stamp_.begin(), scratch.seen_stamp_.end(), 0);
    std::fill(scratch.closed_stamp_.begin(), scratch.closed_stamp_.end(), 0);
    scratch.generation_ = 1;
  }
  const std::uint32_t generation = scratch.generation_;

  // Attach the robot to every vertex it sees (tangent at corners); the goal is attached lazily below.
  scratch.start_links_.clear();
  BlockerCache start_cache;
  BlockerCache goal_cache;
  for (std::uint32_t vertex = 0; vertex < count; ++vertex) {
    const geometry::Point& position = graph.positions_[vertex];
    const bool corner = graph.kinds_[vertex] == VertexKind::Corner;
    const LoopCorner geometry{position, graph.previous_[vertex], graph.next_[vertex], 0};
    if ((!corner || isTangent(geometry, position - start)) &&
        obstacles.visible(start, position, start_cache)) {
      scratch.start_links_.emplace_back(vertex, (position - start).norm());
    }
  }
  result.start_links = scratch.start_links_.size();

  const auto seesGoal = [&](std::uint32_t vertex) {
    const geometry::Point& position = graph.positions_[vertex];
    const bool corner = graph.kinds_[vertex] == VertexKind::Corner;
    const LoopCorner geometry{position, graph.previous_[vertex], graph.next_[vertex], 0};
    return (!corner || isTangent(geometry, position - goal)) && obstacles.visible(position, goal, goal_cache);
  };
  const auto heuristic = [&](std::uint32_t vertex) {
    return vertex == start_index ? (goal - start).norm() : (goal - graph.positions_[vertex]).norm();
  };
  auto& queue = scratch.queue_;
  queue.clear();
  const auto later = [](const SearchScratch::QueueEntry& a, const SearchScratch::QueueEntry& b) {
    return a.priority > b.priority;
  };
  const auto relax = [&](std::uint32_t from, std::uint32_t to, double cost) {
    const double candidate = scratch.cost_so_far_[from] + cost;
    if (scratch.seen_stamp_[to] == generation && candidate >= scratch.cost_so_far_[to]) {
      return;
    }
    if (scratch.closed_stamp_[to] == generation) {
      return;  // consistent heuristic: closed vertices are final
    }
    scratch.seen_stamp_[to] = generation;
    scratch.cost_so_far_[to] = candidate;
    scratch.parent_[to] = from;
    queue.push_back({candidate + (to == goal_index ? 0.0 : heuristic(to)), to});
    std::push_heap(queue.begin(), queue.end(), later);
  };
  scratch.seen_stamp_[start_index] = generation;
  scratch.cost_so_far_[start_index] = 0.0;
  scratch.parent_[start_index] = kNone;
  queue.push_back({heuristic(start_index), start_index});
  bool found = false;
  while (!queue.empty()) {
    std::pop_heap(queue.begin(), queue.end(), later);
    const auto entry = queue.back();
    queue.pop_back();
    const std::uint32_t vertex = entry.vertex;
    if (scratch.closed_stamp_[vertex] == generation) {
      continue;
    }
    scratch.closed_stamp_[vertex] = generation;
    ++result.expansions;
    if (vertex == goal_index) {
      found = true;
      break;
    }
    if (vertex == start_index) {
      for (const auto& [neighbour, distance] : scratch.start_links_) {
        relax(start_index, neighbour, distance);
      }
      continue;
    }
    for (std::uint32_t arc = graph.offsets_[vertex]; arc < graph.offsets_[vertex + 1]; ++arc) {
      relax(vertex, graph.targets_[arc], graph.costs_[arc]);
    }
    // The goal is attached lazily: its link from a vertex only matters once that vertex is expanded,
    // so testing visibility here gives the same result as attaching it to every vertex up front.
    if (seesGoal(vertex)) {
      ++result.goal_links;
      relax(vertex, goal_index, (goal - graph.positions_[vertex]).norm());
    }
  }
  if (!found) {
    result.status = SearchStatus::NoPath;
    return result;
  }
  result.status = SearchStatus::Found;
  result.cost = scratch.cost_so_far_[goal_index];
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
      const std::uint32_t from = chain[index - 1];
      for (std::uint32_t arc = graph.offsets_[from]; arc < graph.offsets_[from + 1]; ++arc) {
        if (graph.targets_[arc] == vertex && graph.interaction_[arc] != kNoInteraction &&
            std::abs(scratch.cost_so_far_[from] + graph.costs_[arc] - scratch.cost_so_far_[vertex]) < 1e-9) {
          point.interaction = graph.interaction_[arc];
          point.object_id = graph.interaction_objects_[point.interaction];
          point.push_plan = graph.interaction_plans_[point.interaction];
          break;
        }
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
