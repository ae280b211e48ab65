#pragma once
// A world's static obstacles as an occupancy grid, so every planner of a comparison and the driven runs'
// loss accounting see the same map: a cell is blocked when its square overlaps a static obstacle with
// positive area (thin walls never fall between cell centres). Movable objects are left out.

#include "common/grid_map/grid_map.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim {

/// The world's extent in cells of `resolution` metres; cells outside every obstacle are free.
grid_map::GridMap rasterizeStaticObstacles(const World& world, double resolution);

}  // namespace ifar::sim
