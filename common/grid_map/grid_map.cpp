#include "common/grid_map/grid_map.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::grid_map {

GridMap::GridMap(int width, int height, double resolution, const geometry::Point& origin, Cell fill)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      resolution_(std::isfinite(resolution) && resolution > 0.0 ? resolution : 1.0),
      origin_(origin),
      cells_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), fill)
{
}

void GridMap::set(int x, int y, Cell state)
{
  if (contains(x, y)) {
    cells_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] =
        state;
  }
}

std::size_t GridMap::count(Cell state) const
{
  return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), state));
}

geometry::Point GridMap::cornerToWorld(double x, double y) const
{
  return origin_ + resolution_ * geometry::Point(x, y);
}

geometry::Point GridMap::worldToGrid(const geometry::Point& world) const
{
  return (world - origin_) / resolution_;
}

geometry::Point GridMap::cellCentre(int x, int y) const
{
  return cornerToWorld(x + 0.5, y + 0.5);
}

CellIndex GridMap::cellAt(const geometry::Point& world) const
{
  const geometry::Point grid = worldToGrid(world);
  return CellIndex{static_cast<int>(std::floor(grid.x())), static_cast<int>(std::floor(grid.y()))};
}

GridMap GridMap::inflated(double radius, UnknownPolicy policy) const
{
  GridMap result = *this;
  if (!(radius > 0.0)) {
    return result;
  }
  // Offsets (in cells) of every cell whose centre lies within radius of the source cell's square.
  const double r = radius / resolution_;
  const int reach = static_cast<int>(std::ceil(r));
  std::vector<CellIndex> offsets;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      // Distance from the neighbour's centre to the source square [0,1]^2 (both in cell units).
      const double gap_x = std::max(0.0, std::abs(dx) - 0.5);
      const double gap_y = std::max(0.0, std::abs(dy) - 0.5);
      if (gap_x * gap_x + gap_y * gap_y <= r * r) {
        offsets.push_back(CellIndex{dx, dy});
      }
    }
  }
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      if (!blocked(x, y, policy)) {
        continue;
      }
      for (const CellIndex& offset : offsets) {
        result.set(x + offset.x, y + offset.y, Cell::Blocked);
      }
    }
  }
  return result;
}

}  // namespace ifar::grid_map
