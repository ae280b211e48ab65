#pragma once
// Exact cell-boundary polygons of the blocked cells, following the GPPC any-angle rules: paths may run
// along obstacle sides but may not pass between two blocked cells that touch only at a corner.

#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/grid_map/grid_map.hpp"

namespace ifar::grid_map {

/// The boundary between blocked and free space as closed loops in world coordinates. Each loop keeps the
/// blocked side on its LEFT (cross product > 0 side, in the grid's own axes): outer boundaries of
/// blocked regions run counter-clockwise, boundaries of free pockets inside them clockwise. Cells
/// outside the grid are blocked, so the map's rim is a loop too. Collinear vertices are dropped.
///
/// Blocked cells that touch only diagonally belong to the same loop: at such a corner the loop turns
/// towards the free cell it is following, so the corner appears twice and is a reflex (270 degree)
/// corner from each free side. A visibility test that treats loop vertices by their wedge therefore
/// forbids squeezing through it.
std::vector<geometry::Polygon> blockedBoundaries(const GridMap& map,
                                                 UnknownPolicy policy = UnknownPolicy::AsFree);

}  // namespace ifar::grid_map
