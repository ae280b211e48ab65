#include "planner/graph/search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "planner/graph/a_star_query.hpp"

namespace ifar::graph {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Vertices per cell of the grid that orders the robot's links (a_star_query.cpp), on average.
constexpr double kVerticesPerCell = 6.0;

}  // namespace

std::string describeNoPath(const SearchResult& result)
{
  if (result.status != SearchStatus::NoPath) {
    return {};
  }
  if (result.start_links == 0) {
    return "no graph vertex is visible from the start: it is enclosed";
  }
  if (!std::isfinite(result.nearest_reached_distance)) {
    return fmt::format("{} vertices are visible from the start and none leads on", result.start_links);
  }
  return fmt::format(
      "the {} vertices reachable from the start do not see the goal: the nearest, at ({:.2f}, {:.2f}), is "
      "{:.2f} m from it (the graph is cut off there)",
      result.expansions - 1, result.nearest_reached.x(), result.nearest_reached.y(),
      result.nearest_reached_distance);
}

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
    case SearchStatus::StartInObstacle:
      return "start_in_obstacle";
    case SearchStatus::GoalInObstacle:
      return "goal_in_obstacle";
  }
  return "unknown";
}

int exitCodeOf(SearchStatus status)
{
  switch (status) {
    case SearchStatus::Found:
      return 0;
    case SearchStatus::NoPath:
      return 1;
    case SearchStatus::InvalidStart:
    case SearchStatus::InvalidGoal:
    case SearchStatus::StartOffMap:
    case SearchStatus::GoalOffMap:
      return 2;
    case SearchStatus::StartInObstacle:
      return 4;
    case SearchStatus::GoalInObstacle:
      return 5;
  }
  return 1;
}

SearchGraph SearchGraph::fromDvGraph(const DvGraph& graph)
{
  SearchGraph result;
  const auto& slots = graph.vertexSlots();
  // Sized exactly: a prior map's snapshot holds hundreds of thousands of arcs, and growth by doubling
  // would leave up to half of each array unused for as long as the map is planned on.
  std::size_t alive = 0;
  std::size_t arcs = 0;
  for (const auto& vertex : slots) {
    if (vertex.alive) {
      ++alive;
      arcs += graph.visibilityLinks(vertex.id).size();
    }
  }
  result.ids_.reserve(alive);
  result.positions_.reserve(alive);
  result.previous_.reserve(alive);
  result.next_.reserve(alive);
  result.kinds_.reserve(alive);
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
  std::size_t interaction_arcs = 0;
  for (std::uint32_t index = 0; index < interactions.size(); ++index) {
    const auto& edge = interactions[index];
    if (edge.alive && graph.contains(edge.from) && graph.contains(edge.to)) {
      outgoing[dense[edge.from]].push_back(index);
      ++interaction_arcs;
    }
  }
  arcs += interaction_arcs;
  result.targets_.reserve(arcs);
  result.costs_.reserve(arcs);
  if (interaction_arcs > 0) {
    result.interaction_.reserve(arcs);
  }
  result.offsets_.reserve(result.ids_.size() + 1);
  result.offsets_.push_back(0);
  for (std::size_t local = 0; local < result.ids_.size(); ++local) {
    for (const auto& link : graph.visibilityLinks(result.ids_[local])) {
      result.targets_.push_back(dense[link.other]);
      result.costs_.push_back(link.length);
      if (interaction_arcs > 0) {
        result.interaction_.push_back(kNoInteraction);
      }
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

SearchGraph SearchGraph::fromCompleteGraph(const DvGraph& graph, const ObstacleSet& obstacles)
{
  SearchGraph result = fromDvGraph(graph);
  if (!result.interaction_.empty()) {
    return result;
  }
  // Positions where two or more obstacle vertices meet (outlines that touch, a loop through one point
  // twice): another vertex's wedge there may fill the sector that a bend away from this corner cuts.
  const auto before = [](const geometry::Point& a, const geometry::Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  };
  std::vector<geometry::Point> positions;
  for (const LoopCorner& corner : obstacles.corners()) {
    positions.push_back(corner.position);
  }
  std::sort(positions.begin(), positions.end(), before);
  std::vector<geometry::Point> shared;
  for (std::size_t index = 1; index < positions.size(); ++index) {
    if (positions[index] == positions[index - 1] && (shared.empty() || shared.back() != positions[index])) {
      shared.push_back(positions[index]);
    }
  }
  result.taut_only_.assign(result.size(), 0);
  for (std::size_t vertex = 0; vertex < result.size(); ++vertex) {
    const bool alone = !std::binary_search(shared.begin(), shared.end(), result.positions_[vertex], before);
    result.taut_only_[vertex] = result.kinds_[vertex] == VertexKind::Corner && alone ? 1 : 0;
  }
  result.sortArcsAroundCorners();
  return result;
}

void SearchGraph::sortArcsAroundCorners()
{
  // A path that reaches a corner with the wedge on its left can only go on wrapping it through the arcs
  // that also have the wedge on their left and turn left (a_star_query.cpp): in the clockwise order from
  // the next edge's direction, a run from the first arc up to the incoming direction. The same mirrored
  // on the right. Sorted so, an expansion stops at the first arc that turns the wrong way.
  left_end_.assign(size(), 0);
  right_end_.assign(size(), 0);
  struct Arc {
    int run;     // 0 left, 1 right, 2 undecided
    double key;  // angle from the run's first direction, in the run's sense (radians)
    std::uint32_t target;
    double cost;
  };
  std::vector<Arc> arcs;
  for (std::size_t vertex = 0; vertex < size(); ++vertex) {
    const std::uint32_t begin = offsets_[vertex];
    const std::uint32_t end = offsets_[vertex + 1];
    left_end_[vertex] = right_end_[vertex] = begin;
    if (taut_only_[vertex] == 0) {
      continue;
    }
    const geometry::Point& position = positions_[vertex];
    const LoopCorner corner{position, previous_[vertex], next_[vertex], 0};
    const geometry::Vector to_next = next_[vertex] - position;
    const geometry::Vector to_previous = previous_[vertex] - position;
    arcs.clear();
    for (std::uint32_t arc = begin; arc < end; ++arc) {
      const geometry::Vector outgoing = positions_[targets_[arc]] - position;
      const int side = wedgeSide(corner, outgoing);
      Arc entry{2, 0.0, targets_[arc], costs_[arc]};
      if (side > 0) {
        entry.run = 0;
        entry.key = -std::atan2(geometry::cross(to_next, outgoing), to_next.dot(outgoing));
      } else if (side < 0) {
        entry.run = 1;
        entry.key = std::atan2(geometry::cross(to_previous, outgoing), to_previous.dot(outgoing));
      }
      arcs.push_back(entry);
    }
    std::sort(arcs.begin(), arcs.end(),
              [](const Arc& a, const Arc& b) { return a.run != b.run ? a.run < b.run : a.key < b.key; });
    for (std::uint32_t index = 0; index < arcs.size(); ++index) {
      targets_[begin + index] = arcs[index].target;
      costs_[begin + index] = arcs[index].cost;
      left_end_[vertex] += arcs[index].run == 0 ? 1 : 0;
      right_end_[vertex] += arcs[index].run <= 1 ? 1 : 0;
    }
  }
}

std::size_t SearchGraph::memoryBytes() const
{
  const auto bytesOf = [](const auto& values) { return values.capacity() * sizeof(values[0]); };
  return bytesOf(ids_) + bytesOf(index_of_) + bytesOf(positions_) + bytesOf(previous_) + bytesOf(next_) +
         bytesOf(kinds_) + bytesOf(taut_only_) + bytesOf(left_end_) + bytesOf(right_end_) +
         bytesOf(offsets_) + bytesOf(targets_) + bytesOf(costs_) + bytesOf(interaction_) +
         bytesOf(interaction_objects_) + bytesOf(interaction_plans_) + bytesOf(interaction_contacts_) +
         bytesOf(interaction_approaches_) + bytesOf(cell_offsets_) + bytesOf(cell_vertices_);
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
                              const WaySurcharge& surcharge, InsideObstacle inside)
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
  result.start = start_in;
  result.goal = goal_in;
  if (inside == InsideObstacle::Refuse && obstacles.isBlocked(start_in)) {
    result.status = SearchStatus::StartInObstacle;
    return result;
  }
  if (inside == InsideObstacle::Refuse && obstacles.isBlocked(goal_in)) {
    result.status = SearchStatus::GoalInObstacle;
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

  Query query(graph, obstacles, start, goal, scratch, preference, surcharge);
  query.run(result);
  return result;
}

}  // namespace ifar::graph
