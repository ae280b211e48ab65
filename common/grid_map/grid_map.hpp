#pragma once
// An occupancy grid for prior maps (MovingAI .map, map_server PGM+YAML) and the simulator's importers.
//
// Frames: cell (x, y) is the square [x, x+1] x [y, y+1] in grid units; in the world it covers
// [origin.x + x*r, origin.x + (x+1)*r] x [origin.y + y*r, origin.y + (y+1)*r] with r = resolution.
// Readers decide how file rows map to y: MovingAI keeps the file's row index (y down, as the GPPC rules
// state; distances do not care), map_server PGM flips rows so that y points up as in ROS.
// Everything outside the grid counts as blocked.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/geometry/point.hpp"

namespace ifar::grid_map {

enum class Cell : std::uint8_t {
  Free = 0,
  Blocked = 1,
  Unknown = 2,  // map_server cells between the free and occupied thresholds
};

/// How unknown cells count when something needs a blocked / free answer.
enum class UnknownPolicy { AsFree, AsBlocked };

struct CellIndex {
  int x = 0;
  int y = 0;
  bool operator==(const CellIndex& other) const { return x == other.x && y == other.y; }
};

class GridMap {
 public:
  GridMap() = default;
  /// A width x height grid, every cell `fill`. Negative sizes count as 0; resolution must be > 0
  /// (a non-positive or non-finite one is replaced by 1 so the value stays usable; readers reject it first).
  GridMap(int width, int height, double resolution, const geometry::Point& origin, Cell fill = Cell::Free);

  int width() const { return width_; }
  int height() const { return height_; }
  /// Metres (or map units) per cell side.
  double resolution() const { return resolution_; }
  /// World position of grid corner (0, 0).
  const geometry::Point& origin() const { return origin_; }

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  /// The cell's state; Blocked outside the grid.
  Cell at(int x, int y) const
  {
    return contains(x, y) ? cells_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                                   static_cast<std::size_t>(x)]
                          : Cell::Blocked;
  }
  /// Ignores cells outside the grid.
  void set(int x, int y, Cell state);
  /// True for Blocked cells, cells outside the grid, and Unknown ones under AsBlocked.
  bool blocked(int x, int y, UnknownPolicy policy = UnknownPolicy::AsFree) const
  {
    const Cell cell = at(x, y);
    return cell == Cell::Blocked || (cell == Cell::Unknown && policy == UnknownPolicy::AsBlocked);
  }
  std::size_t count(Cell state) const;

  /// World position of grid corner (x, y) (corners run 0..width, 0..height).
  geometry::Point cornerToWorld(double x, double y) const;
  /// Grid coordinates (continuous, corner units) of a world point.
  geometry::Point worldToGrid(const geometry::Point& world) const;
  /// World position of the centre of cell (x, y).
  geometry::Point cellCentre(int x, int y) const;
  /// The cell holding a world point (points on a shared side go to the higher index); may be outside.
  CellIndex cellAt(const geometry::Point& world) const;

  /// A copy where every cell whose centre lies within `radius` (world units) of a blocked cell's square
  /// is blocked too (a disc dilation at cell granularity). radius <= 0 returns an unchanged copy. The
  /// map's rim does not grow inwards: a robot of that radius must keep its own distance from the edge.
  GridMap inflated(double radius, UnknownPolicy policy = UnknownPolicy::AsFree) const;

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 1.0;
  geometry::Point origin_ = geometry::Point::Zero();
  std::vector<Cell> cells_;
};

}  // namespace ifar::grid_map
