#include "executive/follower/navigation_field.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

namespace {

/// The window's cells: `side` x `side` squares of `cell` metres, the first with its corner at the origin.
/// Plain doubles here: GCC 12 warns about Eigen temporaries in these loops (false positives).
struct CellGrid {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double cell = 0.0;
  int side = 0;

  std::size_t count() const { return static_cast<std::size_t>(side) * static_cast<std::size_t>(side); }
  std::size_t index(int column, int row) const
  {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(side) + static_cast<std::size_t>(column);
  }
  double distanceFromCentre(int column, int row, double x, double y) const
  {
    return std::hypot(origin_x + (column + 0.5) * cell - x, origin_y + (row + 0.5) * cell - y);
  }
};

/// Distance from each cell centre to the nearest obstacle point, as far as it matters (up to `comfort_m`).
std::vector<double> clearances(common::Span<const geometry::Point> obstacles, const CellGrid& grid,
                               double comfort_m)
{
  const int side = grid.side;
  const double cell = grid.cell;
  // Squared distances pick each cell's nearest point and one hypot per cell measures it: a hypot per
  // point and cell was most of the follower's cycle.
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<double> nearest_squared(grid.count(), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> nearest_point(grid.count(), kNone);
  std::vector<double> centre_x(static_cast<std::size_t>(side));
  std::vector<double> centre_y(static_cast<std::size_t>(side));
  for (int i = 0; i < side; ++i) {
    centre_x[static_cast<std::size_t>(i)] = grid.origin_x + (i + 0.5) * cell;
    centre_y[static_cast<std::size_t>(i)] = grid.origin_y + (i + 0.5) * cell;
  }
  const int reach = static_cast<int>(std::ceil(comfort_m / cell));
  for (std::size_t point_index = 0; point_index < obstacles.size(); ++point_index) {
    const geometry::Point& point = obstacles[point_index];
    if (!point.allFinite()) {
      continue;
    }
    const double offset_x = (point.x() - grid.origin_x) / cell;
    const double offset_y = (point.y() - grid.origin_y) / cell;
    if (offset_x < -reach || offset_y < -reach || offset_x > side + reach || offset_y > side + reach) {
      continue;
    }
    const int column = static_cast<int>(std::floor(offset_x));
    const int row = static_cast<int>(std::floor(offset_y));
    const double x = point.x();
    const double y = point.y();
    for (int r = std::max(0, row - reach); r <= std::min(side - 1, row + reach); ++r) {
      const double dy = centre_y[static_cast<std::size_t>(r)] - y;
      for (int c = std::max(0, column - reach); c <= std::min(side - 1, column + reach); ++c) {
        const double dx = centre_x[static_cast<std::size_t>(c)] - x;
        const double squared = dx * dx + dy * dy;
        const std::size_t i = grid.index(c, r);
        if (squared < nearest_squared[i]) {
          nearest_squared[i] = squared;
          nearest_point[i] = point_index;
        }
      }
    }
  }
  std::vector<double> clearance(grid.count(), comfort_m);
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) {
      const std::size_t i = grid.index(c, r);
      if (nearest_point[i] != kNone) {
        const geometry::Point& point = obstacles[nearest_point[i]];
        clearance[i] = std::min(comfort_m, grid.distanceFromCentre(c, r, point.x(), point.y()));
      }
    }
  }
  return clearance;
}

/// What crossing each cell costs: nothing gets through a blocked cell; the others cost their length
/// times their multiplier.
struct CellCosts {
  std::vector<char> blocked;
  std::vector<double> multiplier;
};

CellCosts cellCosts(const std::vector<double>& clearance, double blocked_m, double comfort_m,
                    double proximity_weight)
{
  CellCosts costs{std::vector<char>(clearance.size(), 0), std::vector<double>(clearance.size(), 1.0)};
  const double band = comfort_m - blocked_m;
  for (std::size_t i = 0; i < clearance.size(); ++i) {
    costs.blocked[i] = clearance[i] < blocked_m ? 1 : 0;
    if (band > 0.0 && clearance[i] < comfort_m) {
      const double closeness = std::min(1.0, (comfort_m - clearance[i]) / band);
      costs.multiplier[i] = 1.0 + proximity_weight * closeness * closeness;
    }
  }
  return costs;
}

using OpenEntry = std::pair<double, std::size_t>;
using OpenSet = std::priority_queue<OpenEntry, std::vector<OpenEntry>, std::greater<OpenEntry>>;

/// Seeds the search at the target: the cells around it when it is inside the window (unblocking them when
/// `open_around_target`, or when none is free), else the window's border cells with their straight-line
/// distance to it.
void seedTarget(const CellGrid& grid, const geometry::Point& target, double blocked_m,
                bool open_around_target, std::vector<char>& blocked, std::vector<double>& cost, OpenSet& open)
{
  const int side = grid.side;
  const double cell = grid.cell;
  const auto seed = [&](int column, int row, double seeded_cost) {
    const std::size_t seeded = grid.index(column, row);
    if (!blocked[seeded] && seeded_cost < cost[seeded]) {
      cost[seeded] = seeded_cost;
      open.emplace(seeded_cost, seeded);
    }
  };
  const double target_x = target.x();
  const double target_y = target.y();
  const double target_column = (target_x - grid.origin_x) / cell;
  const double target_row = (target_y - grid.origin_y) / cell;
  const bool target_inside =
      target_column >= 0.0 && target_row >= 0.0 && target_column < side && target_row < side;
  if (!target_inside) {
    for (int i = 0; i < side; ++i) {
      seed(i, 0, grid.distanceFromCentre(i, 0, target_x, target_y));
      seed(i, side - 1, grid.distanceFromCentre(i, side - 1, target_x, target_y));
      seed(0, i, grid.distanceFromCentre(0, i, target_x, target_y));
      seed(side - 1, i, grid.distanceFromCentre(side - 1, i, target_x, target_y));
    }
    return;
  }
  const int column = static_cast<int>(target_column);
  const int row = static_cast<int>(target_row);
  const double radius = blocked_m + cell;
  const int around = static_cast<int>(std::ceil(radius / cell));
  const auto forEachAround = [&](auto&& visit) {
    for (int r = std::max(0, row - around); r <= std::min(side - 1, row + around); ++r) {
      for (int c = std::max(0, column - around); c <= std::min(side - 1, column + around); ++c) {
        const double distance = grid.distanceFromCentre(c, r, target_x, target_y);
        if (distance <= radius) {
          visit(c, r, distance);
        }
      }
    }
  };
  if (!open_around_target) {
    // A waypoint on the inflated boundary the planner's path hugs: reached from the free cells near it.
    forEachAround([&](int c, int r, double distance) { seed(c, r, distance); });
  }
  if (open.empty()) {
    forEachAround([&](int c, int r, double distance) {
      blocked[grid.index(c, r)] = 0;
      seed(c, r, distance);
    });
  }
}

/// Dijkstra over 8-connected cells from the seeded `open` set; a step costs its length times the mean
/// multiplier of its two cells.
void spreadCost(const CellGrid& grid, const CellCosts& costs, std::vector<double>& cost, OpenSet& open)
{
  const int side = grid.side;
  const double cell = grid.cell;
  const double diagonal = cell * std::sqrt(2.0);
  while (!open.empty()) {
    const auto [current_cost, current] = open.top();
    open.pop();
    if (current_cost > cost[current]) {
      continue;
    }
    const int column = static_cast<int>(current % static_cast<std::size_t>(side));
    const int row = static_cast<int>(current / static_cast<std::size_t>(side));
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        const int c = column + dc;
        const int r = row + dr;
        if ((dc == 0 && dr == 0) || c < 0 || r < 0 || c >= side || r >= side) {
          continue;
        }
        const std::size_t next = grid.index(c, r);
        const double length = (dc != 0 && dr != 0) ? diagonal : cell;
        const double step = length * 0.5 * (costs.multiplier[current] + costs.multiplier[next]);
        if (!costs.blocked[next] && current_cost + step < cost[next]) {
          cost[next] = current_cost + step;
          open.emplace(cost[next], next);
        }
      }
    }
  }
}

}  // namespace

NavigationField::NavigationField(common::Span<const geometry::Point> obstacles, const geometry::Point& centre,
                                 const geometry::Point& target, const NavigationFieldShape& shape)
    : origin_(centre - geometry::Point(shape.half_size_m, shape.half_size_m)),
      cell_size_(shape.cell_size_m),
      cells_per_side_(std::max(2, static_cast<int>(std::ceil(2.0 * shape.half_size_m / shape.cell_size_m))))
{
  const CellGrid grid{origin_.x(), origin_.y(), cell_size_, cells_per_side_};
  const double blocked_m = shape.blocked_m;
  const double comfort_m = std::max(shape.comfort_m, blocked_m);
  CellCosts costs =
      cellCosts(clearances(obstacles, grid, comfort_m), blocked_m, comfort_m, shape.proximity_weight);
  OpenSet open;
  cost_.assign(grid.count(), kUnreachable);
  seedTarget(grid, target, blocked_m, shape.open_around_target, costs.blocked, cost_, open);
  spreadCost(grid, costs, cost_, open);
}

double NavigationField::cellValue(int column, int row) const
{
  if (column < 0 || row < 0 || column >= cells_per_side_ || row >= cells_per_side_) {
    return kUnreachable;
  }
  return cost_[static_cast<std::size_t>(row) * static_cast<std::size_t>(cells_per_side_) +
               static_cast<std::size_t>(column)];
}

double NavigationField::value(const geometry::Point& point) const
{
  const double offset_x = (point.x() - origin_.x()) / cell_size_ - 0.5;
  const double offset_y = (point.y() - origin_.y()) / cell_size_ - 0.5;
  if (!std::isfinite(offset_x) || !std::isfinite(offset_y) || std::abs(offset_x) > 1e6 ||
      std::abs(offset_y) > 1e6) {
    return kUnreachable;
  }
  const int column = static_cast<int>(std::floor(offset_x));
  const int row = static_cast<int>(std::floor(offset_y));
  const double fx = offset_x - column;
  const double fy = offset_y - row;
  const double corners[4] = {cellValue(column, row), cellValue(column + 1, row), cellValue(column, row + 1),
                             cellValue(column + 1, row + 1)};
  if (std::all_of(std::begin(corners), std::end(corners),
                  [](double value) { return std::isfinite(value); })) {
    return (1 - fy) * ((1 - fx) * corners[0] + fx * corners[1]) +
           fy * ((1 - fx) * corners[2] + fx * corners[3]);
  }
  // Next to a blocked cell: the nearest cell's value.
  return cellValue(static_cast<int>(std::lround(offset_x)), static_cast<int>(std::lround(offset_y)));
}

std::optional<double> NavigationField::descentDirection(const geometry::Point& point, double radius_m,
                                                        int directions) const
{
  std::optional<double> best_direction;
  double best_value = kUnreachable;
  const int samples = std::max(4, directions);
  for (int i = 0; i < samples; ++i) {
    const double direction = 2.0 * kPi * i / samples;
    const double sampled =
        value(point + geometry::Point(radius_m * std::cos(direction), radius_m * std::sin(direction)));
    if (sampled < best_value) {
      best_value = sampled;
      best_direction = direction;
    }
  }
  return best_direction;
}

}  // namespace ifar::executive
