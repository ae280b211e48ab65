#include "sim/importers/grid_importer.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "common/grid_map/readers.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_validation.hpp"

namespace ifar::sim {
namespace {

using geometry::Point;

geometry::Polygon rectangleOutline(const grid_map::GridMap& map, double x0, double y0, double x1, double y1)
{
  return {map.cornerToWorld(x0, y0), map.cornerToWorld(x1, y0), map.cornerToWorld(x1, y1),
          map.cornerToWorld(x0, y1)};
}

std::optional<Point> nearestFreeCellToCentre(const grid_map::GridMap& map, grid_map::UnknownPolicy policy)
{
  const double centre_x = 0.5 * map.width();
  const double centre_y = 0.5 * map.height();
  std::optional<Point> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      if (map.blocked(x, y, policy)) {
        continue;
      }
      const double distance = std::hypot(x + 0.5 - centre_x, y + 0.5 - centre_y);
      if (distance < best_distance) {
        best_distance = distance;
        best = map.cellCentre(x, y);
      }
    }
  }
  return best;
}

}  // namespace

std::vector<CellRectangle> blockedRectangles(const grid_map::GridMap& map, grid_map::UnknownPolicy policy)
{
  std::vector<CellRectangle> done;
  // Rectangles still growing, keyed by their column span; a span that does not repeat in the next row
  // is finished.
  std::map<std::pair<int, int>, CellRectangle> open;
  for (int y = 0; y <= map.height(); ++y) {
    std::map<std::pair<int, int>, CellRectangle> next;
    if (y < map.height()) {
      for (int x = 0; x < map.width();) {
        if (!map.blocked(x, y, policy)) {
          ++x;
          continue;
        }
        const int begin = x;
        while (x < map.width() && map.blocked(x, y, policy)) {
          ++x;
        }
        const auto span = std::make_pair(begin, x);
        const auto growing = open.find(span);
        if (growing != open.end()) {
          CellRectangle extended = growing->second;
          extended.y1 = y + 1;
          next.emplace(span, extended);
          open.erase(growing);
        } else {
          next.emplace(span, CellRectangle{begin, y, x, y + 1});
        }
      }
    }
    for (const auto& entry : open) {
      done.push_back(entry.second);
    }
    open = std::move(next);
  }
  return done;
}

WorldResult worldFromGrid(const grid_map::GridMap& map, const std::string& source_name,
                          const GridImportSettings& settings)
{
  if (map.width() <= 0 || map.height() <= 0) {
    return WorldResult::failure(source_name + ": map has no cells");
  }
  World world;
  world.source = source_name;
  const auto slash = source_name.find_last_of('/');
  world.name = source_name.substr(slash == std::string::npos ? 0 : slash + 1);
  const auto dot = world.name.rfind('.');
  if (dot != std::string::npos && dot > 0) {
    world.name.resize(dot);
  }

  int index = 0;
  for (const auto& rectangle : blockedRectangles(map, settings.unknown)) {
    StaticObstacle obstacle;
    obstacle.name = "cells_" + std::to_string(index++);
    obstacle.outline = rectangleOutline(map, rectangle.x0, rectangle.y0, rectangle.x1, rectangle.y1);
    obstacle.outline = geometry::counterClockwise(obstacle.outline);
    obstacle.height_m = settings.wall_height_m;
    obstacle.reflectivity = settings.wall_reflectivity;
    world.obstacles.push_back(std::move(obstacle));
  }
  // One cell thick rim just outside the grid.
  const double w = map.width();
  const double h = map.height();
  const std::tuple<const char*, double, double, double, double> rims[] = {{"rim_low_y", -1, -1, w + 1, 0},
                                                                          {"rim_high_y", -1, h, w + 1, h + 1},
                                                                          {"rim_low_x", -1, 0, 0, h},
                                                                          {"rim_high_x", w, 0, w + 1, h}};
  for (const auto& [name, x0, y0, x1, y1] : rims) {
    StaticObstacle rim;
    rim.name = name;
    rim.outline = geometry::counterClockwise(rectangleOutline(map, x0, y0, x1, y1));
    rim.height_m = settings.wall_height_m;
    rim.reflectivity = settings.wall_reflectivity;
    world.obstacles.push_back(std::move(rim));
  }

  if (settings.start) {
    world.start = *settings.start;
  } else {
    const auto free_cell = nearestFreeCellToCentre(map, settings.unknown);
    if (!free_cell) {
      return WorldResult::failure(source_name + ": map has no free cell for the start");
    }
    world.start.x = free_cell->x();
    world.start.y = free_cell->y();
  }
  for (std::size_t goal = 0; goal < settings.goals.size(); ++goal) {
    world.goals.push_back(Goal{"goal_" + std::to_string(goal), settings.goals[goal]});
  }
  updateBounds(world);
  // Rectangles are valid by construction; a start or goal given by the caller may not be.
  const auto problems = findWorldProblems(world);
  if (!problems.empty()) {
    return WorldResult::failure(describeProblems(source_name, problems));
  }
  return WorldResult::success(std::move(world));
}

WorldResult importGridMapFile(const std::string& path, const GridImportSettings& settings)
{
  const auto read = grid_map::readGridMapFile(path);
  if (!read.ok()) {
    return WorldResult::failure(read.error);
  }
  grid_map::GridMap map = read.map;
  const bool map_server = path.size() > 5 && (path.compare(path.size() - 5, 5, ".yaml") == 0 ||
                                              path.compare(path.size() - 4, 4, ".yml") == 0);
  if (!map_server && settings.movingai_cell_size_m != 1.0) {
    if (!(settings.movingai_cell_size_m > 0.0) || !std::isfinite(settings.movingai_cell_size_m)) {
      return WorldResult::failure(path + ": cell size must be positive");
    }
    grid_map::GridMap scaled(map.width(), map.height(), settings.movingai_cell_size_m, map.origin());
    for (int y = 0; y < map.height(); ++y) {
      for (int x = 0; x < map.width(); ++x) {
        scaled.set(x, y, map.at(x, y));
      }
    }
    map = std::move(scaled);
  }
  return worldFromGrid(map, path, settings);
}

}  // namespace ifar::sim
