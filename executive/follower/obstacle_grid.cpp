#include "executive/follower/obstacle_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ifar::executive {

ObstacleGrid::ObstacleGrid(common::Span<const geometry::Point> points, const geometry::Point& centre,
                           double range_m, double cell_size_m)
    : origin_(centre - geometry::Point(range_m, range_m)), cell_size_(cell_size_m)
{
  if (!(range_m > 0.0) || !(cell_size_m > 0.0) || !centre.allFinite()) {
    throw std::invalid_argument("ObstacleGrid: range and cell size must be positive and the centre finite");
  }
  cells_per_side_ = std::max(1, static_cast<int>(std::ceil(2.0 * range_m / cell_size_m)));
  const std::size_t cell_count =
      static_cast<std::size_t>(cells_per_side_) * static_cast<std::size_t>(cells_per_side_);

  // Counting sort by cell: two passes, no per-cell allocation.
  std::vector<std::size_t> cell_of;
  cell_of.reserve(points.size());
  std::vector<geometry::Point> kept;
  kept.reserve(points.size());
  cell_start_.assign(cell_count + 1, 0);
  for (const geometry::Point& point : points) {
    if (!point.allFinite()) {
      ++skipped_;
      continue;
    }
    const geometry::Point offset = point - origin_;
    if (offset.x() < 0.0 || offset.y() < 0.0 || offset.x() >= 2.0 * range_m || offset.y() >= 2.0 * range_m) {
      continue;
    }
    const std::size_t cell =
        static_cast<std::size_t>(clampedCell(offset.y())) * static_cast<std::size_t>(cells_per_side_) +
        static_cast<std::size_t>(clampedCell(offset.x()));
    cell_of.push_back(cell);
    kept.push_back(point);
    ++cell_start_[cell + 1];
  }
  for (std::size_t cell = 0; cell < cell_count; ++cell) {
    cell_start_[cell + 1] += cell_start_[cell];
  }
  std::vector<std::size_t> next(cell_start_.begin(), cell_start_.end() - 1);
  points_.resize(kept.size());
  for (std::size_t index = 0; index < kept.size(); ++index) {
    points_[next[cell_of[index]]++] = kept[index];
  }
}

int ObstacleGrid::clampedCell(double offset) const
{
  const double cell = std::floor(offset / cell_size_);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(cells_per_side_ - 1)));
}

}  // namespace ifar::executive
