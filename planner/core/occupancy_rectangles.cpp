#include "planner/core/occupancy_rectangles.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ifar::planner {

std::vector<geometry::Polygon> occupancyRectangles(const perception::LayerGrid& grid,
                                                   const std::vector<std::uint8_t>& occupancy,
                                                   const geometry::Point& region_minimum,
                                                   const geometry::Point& region_maximum)
{
  std::vector<geometry::Polygon> rectangles;
  const int cells = grid.cells;
  if (cells <= 0 || occupancy.size() != static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells) ||
      !(grid.cell_size_m > 0.0) || !region_minimum.allFinite() || !region_maximum.allFinite()) {
    return rectangles;
  }
  const double size = grid.cell_size_m;
  // Cells whose centre lies in the region: centre of cell c is origin + (c + 0.5) * size.
  const auto firstCell = [&](double minimum, double origin) {
    return std::clamp(static_cast<int>(std::ceil((minimum - origin) / size - 0.5)), 0, cells);
  };
  const auto lastCell = [&](double maximum, double origin) {
    return std::clamp(static_cast<int>(std::floor((maximum - origin) / size - 0.5)), -1, cells - 1);
  };
  const int column_begin = firstCell(region_minimum.x(), grid.origin.x());
  const int column_end = lastCell(region_maximum.x(), grid.origin.x()) + 1;
  const int row_begin = firstCell(region_minimum.y(), grid.origin.y());
  const int row_end = lastCell(region_maximum.y(), grid.origin.y()) + 1;
  if (column_begin >= column_end || row_begin >= row_end) {
    return rectangles;
  }
  const int columns = column_end - column_begin;
  std::vector<std::uint8_t> taken(
      static_cast<std::size_t>(columns) * static_cast<std::size_t>(row_end - row_begin), 0);
  const auto free = [&](int column, int row) {
    const std::size_t index =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(cells) + static_cast<std::size_t>(column);
    const std::size_t mark = static_cast<std::size_t>(row - row_begin) * static_cast<std::size_t>(columns) +
                             static_cast<std::size_t>(column - column_begin);
    return occupancy[index] == 0 || taken[mark] != 0;
  };
  for (int row = row_begin; row < row_end; ++row) {
    for (int column = column_begin; column < column_end; ++column) {
      if (free(column, row)) {
        continue;
      }
      int right = column + 1;
      while (right < column_end && !free(right, row)) {
        ++right;
      }
      int top = row + 1;
      while (top < row_end) {
        bool full = true;
        for (int check = column; check < right && full; ++check) {
          full = !free(check, top);
        }
        if (!full) {
          break;
        }
        ++top;
      }
      for (int mark_row = row; mark_row < top; ++mark_row) {
        for (int mark_column = column; mark_column < right; ++mark_column) {
          taken[static_cast<std::size_t>(mark_row - row_begin) * static_cast<std::size_t>(columns) +
                static_cast<std::size_t>(mark_column - column_begin)] = 1;
        }
      }
      const double x0 = grid.origin.x() + column * size;
      const double x1 = grid.origin.x() + right * size;
      const double y0 = grid.origin.y() + row * size;
      const double y1 = grid.origin.y() + top * size;
      rectangles.push_back({geometry::Point(x0, y0), geometry::Point(x1, y0), geometry::Point(x1, y1),
                            geometry::Point(x0, y1)});
      column = right - 1;
    }
  }
  return rectangles;
}

}  // namespace ifar::planner
