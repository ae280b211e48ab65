#pragma once
// A small occupancy raster over a window of the local layer, used to tell free-space components apart
// (with and without the movable object). Cells are filled by scanline from polygons.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/interaction/convex_polygon.hpp"

namespace ifar::interaction {

class FreeSpaceRaster {
 public:
  /// Layer bits a cell can carry.
  static constexpr std::uint8_t kObstacle = 1;
  static constexpr std::uint8_t kMovable = 2;

  FreeSpaceRaster(const Bounds& window, double resolution_m);

  /// Marks every cell whose centre lies inside `polygon` (even-odd rule) with `layer`.
  void fill(const geometry::Polygon& polygon, std::uint8_t layer);

  /// A cell and how far its centre lies outside a polygon (0 inside or on its boundary).
  struct CellDistance {
    std::size_t cell = 0;
    double distance_m = 0.0;
  };
  /// The cells whose centre lies inside `polygon` or within `distance_m` of its boundary.
  std::vector<std::size_t> cellsNear(const geometry::Polygon& polygon, double distance_m) const;
  /// The same cells with their distances, so a caller needing two reaches measures once.
  std::vector<CellDistance> cellDistancesNear(const geometry::Polygon& polygon, double distance_m) const;
  void mark(const std::vector<std::size_t>& cells, std::uint8_t layer);
  std::uint8_t layers(std::size_t cell) const { return cells_[cell]; }
  bool onBorder(std::size_t cell) const;

  /// The cells along the window's edge in order round it (each a 4-neighbour of the one before it, the
  /// last one of the first): where free space leaves the window.
  std::vector<std::size_t> borderCells() const;

  /// Visits the cells carrying none of `blocked_layers` 4-connected to `start`, nearest first, with the
  /// number of 4-neighbour steps from `start` to each, until `visit` returns true; returns whether it did.
  /// A template: it runs over thousands of cells for each pose a push search judges.
  template <typename Visit>
  bool searchFrom(std::size_t start, std::uint8_t blocked_layers, Visit&& visit) const
  {
    if (start >= cells_.size() || (cells_[start] & blocked_layers) != 0) {
      return false;
    }
    std::vector<int> steps(cells_.size(), -1);
    std::vector<std::size_t> queue{start};
    steps[start] = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::size_t cell = queue[head];
      if (visit(cell, steps[cell])) {
        return true;
      }
      forEachFreeNeighbour(cell, blocked_layers, [&](std::size_t next) {
        if (steps[next] < 0) {
          steps[next] = steps[cell] + 1;
          queue.push_back(next);
        }
      });
    }
    return false;
  }
  /// The cell nearest `point` within `radius_cells` (Chebyshev rings) carrying none of `blocked_layers`.
  std::optional<std::size_t> nearestFree(const geometry::Point& point, std::uint8_t blocked_layers,
                                         int radius_cells) const;
  std::size_t cellCount() const { return cells_.size(); }

  /// 4-connected components of the cells carrying none of `blocked_layers`; blocked cells get -1.
  std::vector<int> labelComponents(std::uint8_t blocked_layers, int& component_count) const;

  /// The cell index holding `point`, empty outside the window.
  std::optional<std::size_t> cellOf(const geometry::Point& point) const;
  /// The nearest cell within `radius_cells` (Chebyshev rings) whose label is >= 0.
  std::optional<std::size_t> nearestLabelled(const geometry::Point& point, const std::vector<int>& labels,
                                             int radius_cells) const;

 private:
  std::size_t index(int row, int column) const
  {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
           static_cast<std::size_t>(column);
  }
  /// Calls `step(next)` for each 4-neighbour of `cell` inside the window that carries none of `blocked`.
  template <typename Step>
  void forEachFreeNeighbour(std::size_t cell, std::uint8_t blocked, Step&& step) const
  {
    const int row = static_cast<int>(cell / static_cast<std::size_t>(columns_));
    const int column = static_cast<int>(cell % static_cast<std::size_t>(columns_));
    const int neighbours[4][2] = {{row - 1, column}, {row + 1, column}, {row, column - 1}, {row, column + 1}};
    for (const auto& neighbour : neighbours) {
      if (neighbour[0] >= 0 && neighbour[0] < rows_ && neighbour[1] >= 0 && neighbour[1] < columns_) {
        const std::size_t next = index(neighbour[0], neighbour[1]);
        if ((cells_[next] & blocked) == 0) {
          step(next);
        }
      }
    }
  }
  std::optional<std::size_t> nearestCell(const geometry::Point& point, int radius_cells,
                                         const std::function<bool(std::size_t)>& accept) const;

  Bounds window_;
  double resolution_;
  int columns_;
  int rows_;
  std::vector<std::uint8_t> cells_;
};

}  // namespace ifar::interaction
