#pragma once
// Generated worlds as occupancy grids, so every planner of the comparison sees the same map: a cell is
// blocked when its square overlaps a static obstacle with positive area (thin walls never fall between
// cell centres). Movable objects are left out: the search-time comparison is on the static map.

#include "common/grid_map/grid_map.hpp"
#include "sim/world/world.hpp"

namespace ifar::bench {

/// The world's extent in cells of `resolution` metres; cells outside every obstacle are free.
grid_map::GridMap rasterizeStaticObstacles(const sim::World& world, double resolution);

}  // namespace ifar::bench
