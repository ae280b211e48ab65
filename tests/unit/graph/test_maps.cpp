#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph::testing {

grid_map::GridMap mapFromRows(const std::vector<std::string>& rows)
{
  grid_map::GridMap map(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), 1.0,
                        geometry::Point::Zero());
  for (std::size_t y = 0; y < rows.size(); ++y) {
    for (std::size_t x = 0; x < rows[y].size(); ++x) {
      if (rows[y][x] == '@') {
        map.set(static_cast<int>(x), static_cast<int>(y), grid_map::Cell::Blocked);
      }
    }
  }
  return map;
}

}  // namespace ifar::graph::testing
