#include "bench/baselines/grid_astar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ifar::baselines {

namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr std::uint32_t kNoCell = std::numeric_limits<std::uint32_t>::max();

double octile(int dx, int dy)
{
  const double ax = std::abs(dx);
  const double ay = std::abs(dy);
  return std::max(ax, ay) + (kSqrt2 - 1.0) * std::min(ax, ay);
}

// Min-heap on priority: std::push_heap builds a max-heap, so the comparison is reversed.
template <typename Entry>
bool laterFirst(const Entry& first, const Entry& second)
{
  return first.priority > second.priority;
}

}  // namespace

GridAStar::GridAStar(const grid_map::GridMap& map, grid_map::UnknownPolicy policy)
    : width_(map.width()), height_(map.height()), resolution_(map.resolution()), origin_(map.origin())
{
  const std::size_t cells = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  blocked_.resize(cells);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      blocked_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] =
          map.blocked(x, y, policy) ? 1 : 0;
    }
  }
  cost_so_far_.resize(cells);
  parent_.resize(cells);
  seen_stamp_.assign(cells, 0);
  closed_stamp_.assign(cells, 0);
  queue_.reserve(1024);
}

bool GridAStar::freeCellFor(const geometry::Point& point, grid_map::CellIndex& cell) const
{
  if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
    return false;
  }
  const double gx = (point.x() - origin_.x()) / resolution_;
  const double gy = (point.y() - origin_.y()) / resolution_;
  const int base_x = static_cast<int>(std::floor(gx));
  const int base_y = static_cast<int>(std::floor(gy));
  // The holding cell first, then the cells sharing its lower-left corner (a lattice point touches four).
  double best = std::numeric_limits<double>::infinity();
  bool found = false;
  for (int dy = 0; dy >= -1; --dy) {
    for (int dx = 0; dx >= -1; --dx) {
      const int x = base_x + dx;
      const int y = base_y + dy;
      if (blocked(x, y)) {
        continue;
      }
      // Only cells whose square contains the point (closed square) qualify.
      constexpr double kSlack = 1e-9;  // grid units: a lattice point computed in floating point
      if (gx < x - kSlack || gx > x + 1 + kSlack || gy < y - kSlack || gy > y + 1 + kSlack) {
        continue;
      }
      const double distance = std::hypot(gx - (x + 0.5), gy - (y + 0.5));
      if (distance < best) {
        best = distance;
        cell = grid_map::CellIndex{x, y};
        found = true;
      }
    }
  }
  return found;
}

BaselineResult GridAStar::findPath(const geometry::Point& start, const geometry::Point& goal,
                                   GridSearchStats* stats)
{
  grid_map::CellIndex start_cell;
  grid_map::CellIndex goal_cell;
  BaselineResult result;
  if (!freeCellFor(start, start_cell)) {
    result.status = BaselineStatus::InvalidStart;
    result.length = std::numeric_limits<double>::quiet_NaN();
    result.reason = "start is not in a free cell of the grid";
    return result;
  }
  if (!freeCellFor(goal, goal_cell)) {
    result.status = BaselineStatus::InvalidGoal;
    result.length = std::numeric_limits<double>::quiet_NaN();
    result.reason = "goal is not in a free cell of the grid";
    return result;
  }
  result = findPath(start_cell, goal_cell, stats);
  if (result.solved()) {
    result.length += (result.path.front() - start).norm() + (result.path.back() - goal).norm();
    result.path.insert(result.path.begin(), start);
    result.path.push_back(goal);
  }
  return result;
}

BaselineResult GridAStar::findPath(const grid_map::CellIndex& start, const grid_map::CellIndex& goal,
                                   GridSearchStats* stats)
{
  BaselineResult result;
  result.length = std::numeric_limits<double>::quiet_NaN();
  if (blocked(start.x, start.y)) {
    result.status = BaselineStatus::InvalidStart;
    result.reason = "start cell is blocked or off the grid";
    return result;
  }
  if (blocked(goal.x, goal.y)) {
    result.status = BaselineStatus::InvalidGoal;
    result.reason = "goal cell is blocked or off the grid";
    return result;
  }
  ++generation_;
  if (generation_ == 0) {  // wrapped: stamps from 2^32 searches ago would look current
    std::fill(seen_stamp_.begin(), seen_stamp_.end(), 0);
    std::fill(closed_stamp_.begin(), closed_stamp_.end(), 0);
    generation_ = 1;
  }
  const auto index = [this](int x, int y) {
    return static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(width_) + static_cast<std::uint32_t>(x);
  };
  const std::uint32_t start_index = index(start.x, start.y);
  const std::uint32_t goal_index = index(goal.x, goal.y);
  queue_.clear();
  cost_so_far_[start_index] = 0.0;
  parent_[start_index] = kNoCell;
  seen_stamp_[start_index] = generation_;
  queue_.push_back({octile(goal.x - start.x, goal.y - start.y), start_index});

  static constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  static constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  std::size_t expansions = 0;
  bool reached = false;
  while (!queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(), laterFirst<QueueEntry>);
    const std::uint32_t current = queue_.back().cell;
    queue_.pop_back();
    if (closed_stamp_[current] == generation_) {
      continue;  // a stale duplicate (lazy decrease-key)
    }
    closed_stamp_[current] = generation_;
    ++expansions;
    if (current == goal_index) {
      reached = true;
      break;
    }
    const int x = static_cast<int>(current % static_cast<std::uint32_t>(width_));
    const int y = static_cast<int>(current / static_cast<std::uint32_t>(width_));
    const double base_cost = cost_so_far_[current];
    for (int direction = 0; direction < 8; ++direction) {
      const int nx = x + kDx[direction];
      const int ny = y + kDy[direction];
      if (blocked(nx, ny)) {
        continue;
      }
      const bool diagonal = direction >= 4;
      if (diagonal && (blocked(nx, y) || blocked(x, ny))) {
        continue;  // no cutting a corner or squeezing between diagonal neighbours
      }
      const std::uint32_t next = index(nx, ny);
      if (closed_stamp_[next] == generation_) {
        continue;
      }
      const double cost = base_cost + (diagonal ? kSqrt2 : 1.0);
      if (seen_stamp_[next] == generation_ && cost >= cost_so_far_[next]) {
        continue;
      }
      seen_stamp_[next] = generation_;
      cost_so_far_[next] = cost;
      parent_[next] = current;
      queue_.push_back({cost + octile(goal.x - nx, goal.y - ny), next});
      std::push_heap(queue_.begin(), queue_.end(), laterFirst<QueueEntry>);
    }
  }
  if (stats != nullptr) {
    stats->expansions = expansions;
  }
  if (!reached) {
    result.status = BaselineStatus::NoPath;
    result.reason = "goal not reachable on the grid";
    return result;
  }
  for (std::uint32_t cell = goal_index; cell != kNoCell; cell = parent_[cell]) {
    const int x = static_cast<int>(cell % static_cast<std::uint32_t>(width_));
    const int y = static_cast<int>(cell / static_cast<std::uint32_t>(width_));
    result.path.push_back(origin_ + geometry::Point((x + 0.5) * resolution_, (y + 0.5) * resolution_));
  }
  std::reverse(result.path.begin(), result.path.end());
  if (stats != nullptr) {
    stats->path_cells = result.path.size();
  }
  result.status = BaselineStatus::Solved;
  result.length = cost_so_far_[goal_index] * resolution_;
  return result;
}

}  // namespace ifar::baselines
