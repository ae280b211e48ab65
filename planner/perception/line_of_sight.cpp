#include "planner/perception/line_of_sight.hpp"

#include <cmath>
#include <cstddef>

namespace ifar::perception {

bool backgroundClearAlong(const LocalLayer& layer, const geometry::Point& from, const geometry::Point& to,
                          double skip_m)
{
  const LayerGrid& grid = layer.grid;
  const double length = (to - from).norm();
  const auto cells = static_cast<std::size_t>(grid.cells);
  if (!std::isfinite(length) || length <= 2.0 * skip_m || grid.cells <= 0 ||
      layer.background_occupancy.size() != cells * cells) {
    return true;
  }
  const geometry::Point direction = (to - from) / length;
  // Half-cell steps: no cell the segment crosses by more than a corner is missed.
  const double step = 0.5 * grid.cell_size_m;
  for (double along = skip_m; along <= length - skip_m; along += step) {
    const geometry::Point point = from + direction * along;
    const double column = std::floor((point.x() - grid.origin.x()) / grid.cell_size_m);
    const double row = std::floor((point.y() - grid.origin.y()) / grid.cell_size_m);
    if (column < 0.0 || row < 0.0 || column >= grid.cells || row >= grid.cells) {
      continue;
    }
    if (layer.background_occupancy[static_cast<std::size_t>(row) * cells +
                                   static_cast<std::size_t>(column)] != 0) {
      return false;
    }
  }
  return true;
}

}  // namespace ifar::perception
