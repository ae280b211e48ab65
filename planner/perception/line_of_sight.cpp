#include "planner/perception/line_of_sight.hpp"

#include <cmath>
#include <cstddef>
#include <optional>

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
  // An integer count of steps: a summed double would drift and could drop or add the last step.
  const auto steps = static_cast<long>(std::floor((length - 2.0 * skip_m) / step));
  for (long index = 0; index <= steps; ++index) {
    const double along = skip_m + static_cast<double>(index) * step;
    const std::optional<std::size_t> cell = grid.indexOf(from + direction * along);
    if (cell && layer.background_occupancy[*cell] != 0) {
      return false;
    }
  }
  return true;
}

}  // namespace ifar::perception
