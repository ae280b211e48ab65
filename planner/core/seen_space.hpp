#pragma once
// Where the lidar has looked: a coarse grid of the cells seen from some vehicle position, free or not,
// within a range. The search treats unobserved space as free (it is attemptable), but a way through it is
// a guess: a room entered for its unseen far wall is often left again by the same door. With a price on
// the unseen length of a way, a way through what was seen wins over an equally short guess.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "planner/perception/local_layer.hpp"

namespace ifar::planner {

class SeenSpace {
 public:
  /// `cell_size_m`: side of a grid cell (positive).
  explicit SeenSpace(double cell_size_m = 0.5);

  /// Marks what the vehicle at `viewpoint` sees of `layer` within `range_m`: rays fan out from it until an
  /// occupied (inflated) layer cell stops them; that cell counts as seen too. Outside the layer's raster
  /// nothing was returned, so rays go on to the range. A viewpoint inside an obstacle's inflation (the
  /// layer's `inflation_m`) sees out of it. The grid grows to at most 16 million cells (4 km^2); a view
  /// that would take it beyond (a pose jump) starts it afresh.
  void markView(const perception::LocalLayer& layer, const geometry::Point& viewpoint, double range_m,
                double inflation_m);

  bool seen(const geometry::Point& point) const;
  /// Length of the segment from `from` to `to` that lies in unseen cells (outside the grid is unseen).
  double unseenLength(const geometry::Point& from, const geometry::Point& to) const;
  double cellSize() const { return cell_size_m_; }
  std::size_t seenCells() const { return seen_cells_; }

 private:
  /// Grows the grid (never shrinks) to hold the box [minimum, maximum].
  void cover(const geometry::Point& minimum, const geometry::Point& maximum);
  /// Index of the cell holding `point`; empty outside the grid.
  std::optional<std::size_t> indexOf(const geometry::Point& point) const;
  /// Index of a cell inside the grid.
  std::size_t cellIndex(int column, int row) const;
  void mark(const geometry::Point& point);
  bool seenCell(int column, int row) const;

  double cell_size_m_;
  geometry::Point origin_ = geometry::Point::Zero();  // corner of cell (0, 0), on multiples of the cell
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::uint8_t> cells_;  // row-major, 1 = seen
  std::size_t seen_cells_ = 0;
};

}  // namespace ifar::planner
