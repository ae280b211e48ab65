#include "bench/search_comparison/map_scale.hpp"

#include <cmath>
#include <random>

namespace ifar::bench {

grid_map::GridMap tiledMap(const grid_map::GridMap& tile, int width, int height)
{
  const bool empty = tile.width() <= 0 || tile.height() <= 0;
  grid_map::GridMap map(width, height, tile.resolution(), tile.origin(),
                        empty ? grid_map::Cell::Blocked : grid_map::Cell::Free);
  if (empty) {
    return map;
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      map.set(x, y, tile.at(x % tile.width(), y % tile.height()));
    }
  }
  return map;
}

std::vector<grid_map::Scenario> seededFreeCellQueries(const grid_map::GridMap& map, std::size_t count,
                                                      std::uint32_t seed)
{
  std::vector<grid_map::CellIndex> free_cells;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      if (map.at(x, y) == grid_map::Cell::Free) {
        free_cells.push_back({x, y});
      }
    }
  }
  std::vector<grid_map::Scenario> queries;
  if (free_cells.empty()) {
    return queries;
  }
  std::mt19937 generator(seed);
  std::uniform_int_distribution<std::size_t> pick(0, free_cells.size() - 1);
  const auto centre = [](const grid_map::CellIndex& cell) {
    return geometry::Point(cell.x + 0.5, cell.y + 0.5);
  };
  queries.reserve(count);
  for (std::size_t index = 0; index < count; ++index) {
    grid_map::Scenario query;
    query.map_width = map.width();
    query.map_height = map.height();
    query.start = centre(free_cells[pick(generator)]);
    query.goal = centre(free_cells[pick(generator)]);
    query.optimal_length = NAN;
    queries.push_back(query);
  }
  return queries;
}

}  // namespace ifar::bench
