#pragma once
// The map-scale case of `ifar bench-search --gppc-suite`: no public map of 1024 x 1024 cells ships with
// the shared data, so one is made by repeating a dense one, and queried between seeded free cells.
// Repeating keeps the corner density and corridor widths of the real map while the area grows.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/grid_map/grid_map.hpp"
#include "common/grid_map/readers.hpp"

namespace ifar::bench {

/// A width x height grid whose cell (x, y) is `tile`'s cell (x mod tile width, y mod tile height), with
/// `tile`'s resolution and origin. An empty tile gives an all-blocked grid.
grid_map::GridMap tiledMap(const grid_map::GridMap& tile, int width, int height);

/// `count` queries between the centres of free cells of `map`, drawn with `seed` (the same seed, the same
/// queries), in the lattice coordinates of a .scen; no reference length (NaN). None when no cell is free.
std::vector<grid_map::Scenario> seededFreeCellQueries(const grid_map::GridMap& map, std::size_t count,
                                                      std::uint32_t seed);

}  // namespace ifar::bench
