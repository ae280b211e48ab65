#include "sim/world/world_raster.hpp"

#include <algorithm>
#include <cmath>

#include "common/geometry/polygon.hpp"

namespace ifar::sim {
namespace {

/// True when the polygon is an axis-aligned rectangle (4 vertices, every edge parallel to an axis).
bool isAxisAlignedRectangle(const geometry::Polygon& polygon)
{
  if (polygon.size() != 4) {
    return false;
  }
  for (std::size_t index = 0; index < 4; ++index) {
    const geometry::Point edge = polygon[(index + 1) % 4] - polygon[index];
    if (edge.x() != 0.0 && edge.y() != 0.0) {
      return false;
    }
  }
  return true;
}

}  // namespace

grid_map::GridMap rasterizeStaticObstacles(const World& world, double resolution)
{
  const geometry::Point extent = world.bounds_max - world.bounds_min;
  const int width = static_cast<int>(std::ceil(extent.x() / resolution));
  const int height = static_cast<int>(std::ceil(extent.y() / resolution));
  grid_map::GridMap map(width, height, resolution, world.bounds_min, grid_map::Cell::Free);
  // Shrinking the test square by a hair makes a polygon that only touches a cell side leave it free.
  const double shrink = 1e-6 * resolution;
  for (const StaticObstacle& obstacle : world.obstacles) {
    if (obstacle.outline.size() < 3) {
      continue;
    }
    geometry::Point low = obstacle.outline.front();
    geometry::Point high = obstacle.outline.front();
    for (const geometry::Point& vertex : obstacle.outline) {
      low = low.cwiseMin(vertex);
      high = high.cwiseMax(vertex);
    }
    const geometry::Point grid_low = map.worldToGrid(low);
    const geometry::Point grid_high = map.worldToGrid(high);
    const int x_begin = std::max(0, static_cast<int>(std::floor(grid_low.x())));
    const int y_begin = std::max(0, static_cast<int>(std::floor(grid_low.y())));
    const int x_end = std::min(width - 1, static_cast<int>(std::floor(grid_high.x())));
    const int y_end = std::min(height - 1, static_cast<int>(std::floor(grid_high.y())));
    if (isAxisAlignedRectangle(obstacle.outline)) {
      // Rectangles (walls, rock): a cell is blocked when its square, shrunk as below, overlaps the
      // rectangle, which is an interval test per axis; the same answer as the general test, far faster.
      const double tolerance = 1e-6;  // the shrink, in cell units
      for (int y = y_begin; y <= y_end; ++y) {
        for (int x = x_begin; x <= x_end; ++x) {
          if (x + 1 - tolerance > grid_low.x() && x + tolerance < grid_high.x() &&
              y + 1 - tolerance > grid_low.y() && y + tolerance < grid_high.y()) {
            map.set(x, y, grid_map::Cell::Blocked);
          }
        }
      }
      continue;
    }
    for (int y = y_begin; y <= y_end; ++y) {
      for (int x = x_begin; x <= x_end; ++x) {
        if (map.at(x, y) == grid_map::Cell::Blocked) {
          continue;
        }
        const geometry::Point corner = map.cornerToWorld(x, y);
        const geometry::Polygon square{corner + geometry::Point(shrink, shrink),
                                       corner + geometry::Point(resolution - shrink, shrink),
                                       corner + geometry::Point(resolution - shrink, resolution - shrink),
                                       corner + geometry::Point(shrink, resolution - shrink)};
        if (geometry::polygonsIntersect(square, obstacle.outline)) {
          map.set(x, y, grid_map::Cell::Blocked);
        }
      }
    }
  }
  return map;
}

}  // namespace ifar::sim
