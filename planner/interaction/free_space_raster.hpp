#pragma once
// A small occupancy raster over a window of the local layer, used to tell free-space components apart
// (with and without the movable object). Cells are filled by scanline from polygons.

#include <cstddef>
#include <cstdint>
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

  /// 4-connected components of the cells carrying none of `blocked_layers`; blocked cells get -1.
  std::vector<int> labelComponents(std::uint8_t blocked_layers, int& component_count) const;

  /// The cell index holding `point`, empty outside the window.
  std::optional<std::size_t> cellOf(const geometry::Point& point) const;
  /// The nearest cell within `radius_cells` (Chebyshev rings) whose label is >= 0.
  std::optional<std::size_t> nearestLabelled(const geometry::Point& point, const std::vector<int>& labels,
                                             int radius_cells) const;

 private:
  Bounds window_;
  double resolution_;
  int columns_;
  int rows_;
  std::vector<std::uint8_t> cells_;
};

}  // namespace ifar::interaction
