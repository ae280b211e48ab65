#pragma once
// Buckets obstacle points into square cells around a centre, so a footprint check looks at the few
// points near it instead of every point.

#include <cstddef>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"

namespace ifar::executive {

class ObstacleGrid {
 public:
  /// Keeps the points within `range_m` (Chebyshev distance) of `centre`; cells are `cell_size_m` wide.
  /// Non-finite points are counted in skippedPoints() and left out. Sizes must be positive.
  ObstacleGrid(common::Span<const geometry::Point> points, const geometry::Point& centre, double range_m,
               double cell_size_m);

  /// Calls `visit(point)` for every kept point in the cells touched by the square of half-size
  /// `radius_m` around `query` (a superset of the points within `radius_m`).
  template <typename Visitor>
  void forEachNear(const geometry::Point& query, double radius_m, Visitor&& visit) const
  {
    const int first_column = clampedCell(query.x() - radius_m - origin_.x());
    const int last_column = clampedCell(query.x() + radius_m - origin_.x());
    const int first_row = clampedCell(query.y() - radius_m - origin_.y());
    const int last_row = clampedCell(query.y() + radius_m - origin_.y());
    for (int row = first_row; row <= last_row; ++row) {
      for (int column = first_column; column <= last_column; ++column) {
        const std::size_t cell = static_cast<std::size_t>(row * cells_per_side_ + column);
        for (std::size_t index = cell_start_[cell]; index < cell_start_[cell + 1]; ++index) {
          visit(points_[index]);
        }
      }
    }
  }

  std::size_t size() const { return points_.size(); }
  std::size_t skippedPoints() const { return skipped_; }

 private:
  int clampedCell(double offset) const;

  geometry::Point origin_;
  double cell_size_;
  int cells_per_side_;
  std::vector<std::size_t> cell_start_;  // cells_per_side^2 + 1 offsets into points_
  std::vector<geometry::Point> points_;  // sorted by cell
  std::size_t skipped_ = 0;
};

}  // namespace ifar::executive
