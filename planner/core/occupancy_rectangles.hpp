#pragma once
// The local layer's inflated background occupancy as axis-aligned rectangles, for the interaction
// planner's scene. The layer's background polygons cannot be used as they are: a building is one outer
// polygon with free-space holes (the rooms), and the interaction planner takes obstacles only. Greedy
// maximal rows-then-columns rectangles keep axis-aligned walls to a few pieces.

#include <cstdint>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/perception/local_layer.hpp"

namespace ifar::planner {

/// Occupied cells (value != 0, row-major, grid.cells x grid.cells) whose centres lie in
/// [region_minimum, region_maximum], merged into counter-clockwise rectangles covering whole cells.
/// A mismatched occupancy size gives no rectangles.
std::vector<geometry::Polygon> occupancyRectangles(const perception::LayerGrid& grid,
                                                   const std::vector<std::uint8_t>& occupancy,
                                                   const geometry::Point& region_minimum,
                                                   const geometry::Point& region_maximum);

}  // namespace ifar::planner
