#include "executive/follower/navigation_field.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

NavigationField::NavigationField(common::Span<const geometry::Point> obstacles, const geometry::Point& centre,
                                 const geometry::Point& target, const NavigationFieldShape& shape)
    : origin_(centre - geometry::Point(shape.half_size_m, shape.half_size_m)),
      cell_size_(shape.cell_size_m),
      cells_per_side_(std::max(2, static_cast<int>(std::ceil(2.0 * shape.half_size_m / shape.cell_size_m))))
{
  const int side = cells_per_side_;
  const std::size_t cells = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
  const auto index = [side](int column, int row) {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(side) + static_cast<std::size_t>(column);
  };
  // Plain doubles here: GCC 12 warns about Eigen temporaries in these loops (false positives).
  const double origin_x = origin_.x();
  const double origin_y = origin_.y();
  const double cell = cell_size_;
  const auto distanceFromCentre = [origin_x, origin_y, cell](int column, int row, double x, double y) {
    return std::hypot(origin_x + (column + 0.5) * cell - x, origin_y + (row + 0.5) * cell - y);
  };

  // Distance from each cell centre to the nearest obstacle point, as far as it matters.
  const double blocked_m = shape.blocked_m;
  const double comfort_m = std::max(shape.comfort_m, blocked_m);
  // Squared distances pick each cell's nearest point and one hypot per cell measures it: a hypot per
  // point and cell was most of the follower's cycle.
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<double> nearest_squared(cells, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> nearest_point(cells, kNone);
  std::vector<double> centre_x(static_cast<std::size_t>(side));
  std::vector<double> centre_y(static_cast<std::size_t>(side));
  for (int i = 0; i < side; ++i) {
    centre_x[static_cast<std::size_t>(i)] = origin_x + (i + 0.5) * cell;
    centre_y[static_cast<std::size_t>(i)] = origin_y + (i + 0.5) * cell;
  }
  const int reach = static_cast<int>(std::ceil(comfort_m / cell));
  for (std::size_t point_index = 0; point_index < obstacles.size(); ++point_index) {
    const geometry::Point& point = obstacles[point_index];
    if (!point.allFinite()) {
      continue;
    }
    const double offset_x = (point.x() - origin_x) / cell;
    const double offset_y = (point.y() - origin_y) / cell;
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
        const std::size_t i = index(c, r);
        if (squared < nearest_squared[i]) {
          nearest_squared[i] = squared;
          nearest_point[i] = point_index;
        }
      }
    }
  }
  std::vector<double> clearance(cells, comfort_m);
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) {
      const std::size_t i = index(c, r);
      if (nearest_point[i] != kNone) {
        const geometry::Point& point = obstacles[nearest_point[i]];
        clearance[i] = std::min(comfort_m, distanceFromCentre(c, r, point.x(), point.y()));
      }
    }
  }
  std::vector<char> blocked(cells, 0);
  std::vector<double> multiplier(cells, 1.0);
  const double band = comfort_m - blocked_m;
  for (std::size_t i = 0; i < cells; ++i) {
    blocked[i] = clearance[i] < blocked_m ? 1 : 0;
    if (band > 0.0 && clearance[i] < comfort_m) {
      const double closeness = std::min(1.0, (comfort_m - clearance[i]) / band);
      multiplier[i] = 1.0 + shape.proximity_weight * closeness * closeness;
    }
  }

  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost_.assign(cells, kUnreachable);
  const auto seed = [&](int column, int row, double cost) {
    const std::size_t seeded = index(column, row);
    if (!blocked[seeded] && cost < cost_[seeded]) {
      cost_[seeded] = cost;
      open.emplace(cost, seeded);
    }
  };
  const double target_x = target.x();
  const double target_y = target.y();
  const double target_column = (target_x - origin_x) / cell;
  const double target_row = (target_y - origin_y) / cell;
  const bool target_inside =
      target_column >= 0.0 && target_row >= 0.0 && target_column < side && target_row < side;
  if (target_inside) {
    const int column = static_cast<int>(target_column);
    const int row = static_cast<int>(target_row);
    const double radius = blocked_m + cell;
    const int around = static_cast<int>(std::ceil(radius / cell));
    const auto forEachAround = [&](auto&& visit) {
      for (int r = std::max(0, row - around); r <= std::min(side - 1, row + around); ++r) {
        for (int c = std::max(0, column - around); c <= std::min(side - 1, column + around); ++c) {
          const double distance = distanceFromCentre(c, r, target_x, target_y);
          if (distance <= radius) {
            visit(c, r, distance);
          }
        }
      }
    };
    if (!shape.open_around_target) {
      // A waypoint on the inflated boundary the planner's path hugs: reached from the free cells near it.
      forEachAround([&](int c, int r, double distance) { seed(c, r, distance); });
    }
    if (open.empty()) {
      forEachAround([&](int c, int r, double distance) {
        blocked[index(c, r)] = 0;
        seed(c, r, distance);
      });
    }
  } else {
    for (int i = 0; i < side; ++i) {
      seed(i, 0, distanceFromCentre(i, 0, target_x, target_y));
      seed(i, side - 1, distanceFromCentre(i, side - 1, target_x, target_y));
      seed(0, i, distanceFromCentre(0, i, target_x, target_y));
      seed(side - 1, i, distanceFromCentre(side - 1, i, target_x, target_y));
    }
  }

  // Dijkstra over 8-connected cells; a step costs its length times the mean multiplier of its two cells.
  const double diagonal = cell * std::sqrt(2.0);
  while (!open.empty()) {
    const auto [cost, current] = open.top();
    open.pop();
    if (cost > cost_[current]) {
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
        const std::size_t next = index(c, r);
        const double length = (dc != 0 && dr != 0) ? diagonal : cell;
        const double step = length * 0.5 * (multiplier[current] + multiplier[next]);
        if (!blocked[next] && cost + step < cost_[next]) {
          cost_[next] = cost + step;
          open.emplace(cost_[next], next);
        }
      }
    }
  }
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
