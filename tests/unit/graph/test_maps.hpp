#pragma once
// Small hand-drawn maps for the graph tests: '@' blocked, anything else free; row r is y = r.

#include <string>
#include <vector>

#include "common/grid_map/grid_map.hpp"

namespace ifar::graph::testing {

grid_map::GridMap mapFromRows(const std::vector<std::string>& rows);

}  // namespace ifar::graph::testing
