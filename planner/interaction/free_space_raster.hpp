#pragma once
// A small occupancy raster over a window of the local layer, used to tell free-space components apart
// (with and without the movable object). Cells are filled by scanline from polygons.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
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

  /// The buffers searchFrom() works in, kept between searches so that a search run for every pose a push
  /// search judges neither allocates nor clears raster-sized memory. One per thread of searches; any
  /// raster may use it.
  class SearchScratch {
   private:
    friend class FreeSpaceRaster;
    struct Queued {
      std::size_t cell;
      int column;  // so that the cell's neighbours are found without a division
    };
    std::vector<std::uint32_t> stamps;  // the search that last reached (or closed) each cell
    std::vector<int> steps;             // valid where the current search reached the cell
    std::vector<Queued> queue;
    std::uint32_t search = 0;
  };

  /// Visits the cells carrying none of `blocked_layers` 4-connected to `start`, nearest first, with the
  /// number of 4-neighbour steps from `start` to each, until `visit` returns true; returns whether it did.
  /// A template: it runs over thousands of cells for each pose a push search judges.
  template <typename Visit>
  bool searchFrom(std::size_t start, std::uint8_t blocked_layers, Visit&& visit) const
  {
    SearchScratch scratch;
    return searchFrom(start, blocked_layers, {}, scratch, std::forward<Visit>(visit));
  }
  /// The same search with the cells of `closed` blocked as well (the raster with an object's cells marked,
  /// without a copy of it), in `scratch`'s buffers.
  template <typename Visit>
  bool searchFrom(std::size_t start, std::uint8_t blocked_layers, const std::vector<std::size_t>& closed,
                  SearchScratch& scratch, Visit&& visit) const
  {
    if (start >= cells_.size() || (cells_[start] & blocked_layers) != 0) {
      return false;
    }
    if (scratch.stamps.size() < cells_.size() ||
        scratch.search == std::numeric_limits<std::uint32_t>::max()) {
      scratch.stamps.assign(std::max(scratch.stamps.size(), cells_.size()), 0);
      scratch.steps.resize(scratch.stamps.size());
      scratch.search = 0;
    }
    const std::uint32_t search = ++scratch.search;
    std::vector<std::uint32_t>& stamps = scratch.stamps;
    std::vector<int>& steps = scratch.steps;
    for (const std::size_t cell : closed) {
      stamps[cell] = search;  // taken as reached: never queued
    }
    if (stamps[start] == search) {
      return false;
    }
    std::vector<SearchScratch::Queued>& queue = scratch.queue;
    queue.clear();
    queue.push_back(
        SearchScratch::Queued{start, static_cast<int>(start % static_cast<std::size_t>(columns_))});
    stamps[start] = search;
    steps[start] = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const SearchScratch::Queued current = queue[head];
      const std::size_t cell = current.cell;
      if (visit(cell, steps[cell])) {
        return true;
      }
      forEachFreeNeighbour(cell, current.column, blocked_layers, [&](std::size_t next, int column) {
        if (stamps[next] != search) {
          stamps[next] = search;
          steps[next] = steps[cell] + 1;
          queue.push_back(SearchScratch::Queued{next, column});
        }
      });
    }
    return false;
  }
  /// The cell nearest `point` within `radius_cells` (Chebyshev rings) carrying none of `blocked_layers`.
  std::optional<std::size_t> nearestFree(const geometry::Point& point, std::uint8_t blocked_layers,
                                         int radius_cells) const;
  /// The same, with the cells of `closed_sorted` (ascending) taken as blocked too.
  std::optional<std::size_t> nearestFree(const geometry::Point& point, std::uint8_t blocked_layers,
                                         int radius_cells,
                                         const std::vector<std::size_t>& closed_sorted) const;
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
  /// Calls `step(next, next_column)` for each 4-neighbour of `cell` (in `column`) inside the window that
  /// carries none of `blocked`: the row before, the row after, the column before, the column after. The
  /// caller passes the column, so a search that carries it finds the neighbours without a division.
  template <typename Step>
  void forEachFreeNeighbour(std::size_t cell, int column, std::uint8_t blocked, Step&& step) const
  {
    const auto columns = static_cast<std::size_t>(columns_);
    const auto visit = [&](std::size_t next, int next_column) {
      if ((cells_[next] & blocked) == 0) {
        step(next, next_column);
      }
    };
    if (cell >= columns) {
      visit(cell - columns, column);
    }
    if (cell + columns < cells_.size()) {
      visit(cell + columns, column);
    }
    if (column > 0) {
      visit(cell - 1, column - 1);
    }
    if (column + 1 < columns_) {
      visit(cell + 1, column + 1);
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
