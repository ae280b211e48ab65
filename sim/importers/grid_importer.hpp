#pragma once
// Grid maps (MovingAI .map, map_server PGM+YAML, read by common/grid_map) to worlds: blocked cells are
// merged into axis-aligned rectangles (maximal runs along rows, stacked while rows repeat), each a static
// obstacle, plus a rim of walls around the grid because everything outside it counts as blocked.

#include <optional>
#include <string>
#include <vector>

#include "common/geometry/pose2.hpp"
#include "common/grid_map/grid_map.hpp"
#include "sim/world/world_result.hpp"

namespace ifar::sim {

struct GridImportSettings {
  /// Metres per cell for MovingAI maps, whose cells have no size (map_server files carry their own).
  double movingai_cell_size_m = 1.0;
  /// How map_server cells between the free and occupied thresholds count. Blocked by default: the
  /// vehicle should not drive where the map does not say it is free.
  grid_map::UnknownPolicy unknown = grid_map::UnknownPolicy::AsBlocked;
  double wall_height_m = 2.0;
  double wall_reflectivity = 0.2;
  /// Vehicle start; by default the free cell nearest the grid's centre.
  std::optional<geometry::Pose2> start;
  std::vector<geometry::Point> goals;
};

/// Converts a grid already in memory; `source_name` names it in messages and world.source.
WorldResult worldFromGrid(const grid_map::GridMap& map, const std::string& source_name,
                          const GridImportSettings& settings);

/// Reads a .map or a map_server .yaml (by extension) and converts it. Errors name the file and the line.
WorldResult importGridMapFile(const std::string& path, const GridImportSettings& settings);

/// The blocked cells as rectangles in cell units (x0, y0, x1, y1), cells [x0, x1) x [y0, y1).
struct CellRectangle {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;
};
std::vector<CellRectangle> blockedRectangles(const grid_map::GridMap& map, grid_map::UnknownPolicy policy);

}  // namespace ifar::sim
