#include "bench/scenarios/scenario_worlds.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include "bench/scenarios/namosim_worlds.hpp"
#include "common/grid_map/readers.hpp"
#include "sim/generators/generators.hpp"
#include "sim/importers/grid_importer.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_validation.hpp"

namespace ifar::scenarios {
namespace {

// The generator's office corridor (sim/generators/office_generator.cpp): between these y.
constexpr double kOfficeCorridorLow = 10.75;
constexpr double kOfficeCorridorHigh = 13.25;

struct Box {
  geometry::Point low;
  geometry::Point high;
};

Box boxOf(const geometry::Polygon& polygon)
{
  Box box{polygon.front(), polygon.front()};
  for (const geometry::Point& vertex : polygon) {
    box.low = box.low.cwiseMin(vertex);
    box.high = box.high.cwiseMax(vertex);
  }
  return box;
}

geometry::Polygon rectangle(double x0, double y0, double x1, double y1)
{
  return {geometry::Point(x0, y0), geometry::Point(x1, y0), geometry::Point(x1, y1), geometry::Point(x0, y1)};
}

/// Index of the outer wall on the east (east = true) or west side: a thin obstacle on the world's
/// bounding box spanning most of its height; -1 when there is none.
int outerWall(const sim::World& world, bool east)
{
  const double height = world.bounds_max.y() - world.bounds_min.y();
  for (std::size_t index = 0; index < world.obstacles.size(); ++index) {
    const Box box = boxOf(world.obstacles[index].outline);
    const bool on_side = east ? std::abs(box.high.x() - world.bounds_max.x()) < 1e-9
                              : std::abs(box.low.x() - world.bounds_min.x()) < 1e-9;
    if (on_side && box.high.x() - box.low.x() < 0.5 && box.high.y() - box.low.y() > 0.8 * height) {
      return static_cast<int>(index);
    }
  }
  return -1;
}

/// True when `point` is inside a static obstacle other than `skip`.
bool insideOtherObstacle(const sim::World& world, const geometry::Point& point, int skip)
{
  for (std::size_t index = 0; index < world.obstacles.size(); ++index) {
    if (static_cast<int>(index) != skip && geometry::containsPoint(world.obstacles[index].outline, point)) {
      return true;
    }
  }
  return false;
}

/// Replaces the wall with two pieces leaving the corridor open.
void openCorridor(sim::World& world, int wall_index)
{
  const sim::StaticObstacle wall = world.obstacles[static_cast<std::size_t>(wall_index)];
  const Box box = boxOf(wall.outline);
  sim::StaticObstacle lower = wall;
  lower.name = wall.name + "_south";
  lower.outline = rectangle(box.low.x(), box.low.y(), box.high.x(), kOfficeCorridorLow);
  sim::StaticObstacle upper = wall;
  upper.name = wall.name + "_north";
  upper.outline = rectangle(box.low.x(), kOfficeCorridorHigh, box.high.x(), box.high.y());
  world.obstacles[static_cast<std::size_t>(wall_index)] = lower;
  world.obstacles.push_back(upper);
}

/// Free-run lengths through a cell along x and y, in cells, and where the runs start.
struct Runs {
  int x_begin = 0;
  int x_end = 0;  // exclusive
  int y_begin = 0;
  int y_end = 0;
};

Runs freeRuns(const grid_map::GridMap& grid, int x, int y, int limit)
{
  const auto free = [&grid](int cx, int cy) {
    return !grid.blocked(cx, cy, grid_map::UnknownPolicy::AsBlocked);
  };
  Runs runs{x, x + 1, y, y + 1};
  while (runs.x_begin > 0 && x - runs.x_begin < limit && free(runs.x_begin - 1, y)) {
    --runs.x_begin;
  }
  while (runs.x_end < grid.width() && runs.x_end - x < limit && free(runs.x_end, y)) {
    ++runs.x_end;
  }
  while (runs.y_begin > 0 && y - runs.y_begin < limit && free(x, runs.y_begin - 1)) {
    --runs.y_begin;
  }
  while (runs.y_end < grid.height() && runs.y_end - y < limit && free(x, runs.y_end)) {
    ++runs.y_end;
  }
  return runs;
}

/// True when every cell the world-frame box touches is free.
bool boxFree(const grid_map::GridMap& grid, const Box& box)
{
  const geometry::Point low = grid.worldToGrid(box.low);
  const geometry::Point high = grid.worldToGrid(box.high);
  for (int y = static_cast<int>(std::floor(low.y())); y <= static_cast<int>(std::floor(high.y())); ++y) {
    for (int x = static_cast<int>(std::floor(low.x())); x <= static_cast<int>(std::floor(high.x())); ++x) {
      if (grid.blocked(x, y, grid_map::UnknownPolicy::AsBlocked)) {
        return false;
      }
    }
  }
  return true;
}

/// Uniform in [low, high) from the engine's raw output (std:: distributions differ between libraries).
double uniform(std::mt19937_64& random, double low, double high)
{
  return low + (high - low) * static_cast<double>(random() >> 11) * (1.0 / 9007199254740992.0);
}

sim::MovableObject makeBox(std::int64_t id, const geometry::Point& centre, double size_x, double size_y,
                           bool light, std::mt19937_64& random)
{
  sim::MovableObject object;
  object.id = id;
  object.name = std::string(light ? "light_box_" : "heavy_box_") + std::to_string(id);
  object.outline = rectangle(-0.5 * size_x, -0.5 * size_y, 0.5 * size_x, 0.5 * size_y);
  object.pose = geometry::Pose2{centre.x(), centre.y(), 0.0};
  // The generators' weight classes: light slides with at most ~236 N, heavy needs at least ~1,470 N.
  object.mass_kg =
      std::round((light ? uniform(random, 15.0, 40.0) : uniform(random, 250.0, 400.0)) * 10.0) / 10.0;
  object.ground_friction =
      std::round((light ? uniform(random, 0.4, 0.6) : uniform(random, 0.6, 0.8)) * 100.0) / 100.0;
  object.height_m = light ? 0.8 : 1.2;
  return object;
}

sim::WorldResult validated(sim::World world)
{
  sim::updateBounds(world);
  const auto problems = sim::findWorldProblems(world);
  if (!problems.empty()) {
    return sim::WorldResult::failure(sim::describeProblems(world.source, problems));
  }
  return sim::WorldResult::success(std::move(world));
}

bool fileExists(const std::string& path)
{
  return !path.empty() && std::ifstream(path).good();
}

std::string seeded(const std::string& prefix, std::uint64_t seed)
{
  return prefix + "-" + std::to_string(seed);
}

}  // namespace

sim::WorldResult joinOfficesAlongCorridor(const sim::World& west, const sim::World& east)
{
  const int west_wall = outerWall(west, true);
  const int east_wall = outerWall(east, false);
  const double corridor_mid = 0.5 * (kOfficeCorridorLow + kOfficeCorridorHigh);
  // The generator's layout: the corridor open where the worlds meet, with its two walls beside it.
  const auto corridor_at = [&corridor_mid](const sim::World& world, double x, int wall) {
    return !insideOtherObstacle(world, {x, corridor_mid}, wall) &&
           insideOtherObstacle(world, {x, kOfficeCorridorLow - 0.1}, wall) &&
           insideOtherObstacle(world, {x, kOfficeCorridorHigh + 0.1}, wall);
  };
  if (west_wall < 0 || east_wall < 0 || !corridor_at(west, west.bounds_max.x() - 0.3, west_wall) ||
      !corridor_at(east, east.bounds_min.x() + 0.3, east_wall)) {
    return sim::WorldResult::failure(west.source + " + " + east.source +
                                     ": not the office generator's layout (no outer wall beside an open "
                                     "corridor at y = 10.75-13.25 m)");
  }
  sim::World joined = west;
  joined.name = "office2x";
  joined.source = "joined offices: " + west.source + " | " + east.source;
  openCorridor(joined, west_wall);

  sim::World shifted = east;
  openCorridor(shifted, east_wall);
  const geometry::Point offset(west.bounds_max.x() - east.bounds_min.x(), 0.0);
  std::int64_t next_id = 1;
  for (const sim::MovableObject& object : joined.objects) {
    next_id = std::max(next_id, object.id + 1);
  }
  for (sim::StaticObstacle obstacle : shifted.obstacles) {
    obstacle.name = "east_" + obstacle.name;
    for (geometry::Point& vertex : obstacle.outline) {
      vertex += offset;
    }
    joined.obstacles.push_back(std::move(obstacle));
  }
  for (sim::MovableObject object : shifted.objects) {
    object.id = next_id++;
    object.name = "east_" + object.name;
    object.pose.x += offset.x();
    object.pose.y += offset.y();
    joined.objects.push_back(std::move(object));
  }
  joined.goals.clear();
  for (const sim::Goal& goal : shifted.goals) {
    joined.goals.push_back(sim::Goal{goal.name, goal.position + offset});
  }
  return validated(std::move(joined));
}

sim::WorldResult willowWithObjects(const std::string& map_yaml, std::uint64_t seed)
{
  sim::GridImportSettings import_settings;
  sim::WorldResult imported = sim::importGridMapFile(map_yaml, import_settings);
  if (!imported.ok()) {
    return imported;
  }
  const grid_map::MapReadResult read = grid_map::readGridMapFile(map_yaml);
  if (!read.ok()) {
    return sim::WorldResult::failure(read.error);
  }
  const grid_map::GridMap& grid = read.map;
  sim::World world = imported.world();
  world.name = "willow";

  std::vector<grid_map::CellIndex> free_cells;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (!grid.blocked(x, y, grid_map::UnknownPolicy::AsBlocked)) {
        free_cells.push_back({x, y});
      }
    }
  }
  if (free_cells.empty()) {
    return sim::WorldResult::failure(map_yaml + ": no free cell to place objects in");
  }
  const double resolution = grid.resolution();
  const int limit = static_cast<int>(std::ceil(8.0 / resolution));
  constexpr int kDoorBoxes = 10;
  constexpr int kCorridorBoxes = 4;
  std::mt19937_64 random(seed);
  int doors = 0;
  int corridors = 0;
  std::vector<geometry::Point> placed;
  for (int attempt = 0; attempt < 40000 && (doors < kDoorBoxes || corridors < kCorridorBoxes); ++attempt) {
    const grid_map::CellIndex cell = free_cells[random() % free_cells.size()];
    const Runs runs = freeRuns(grid, cell.x, cell.y, limit);
    const double across_x = (runs.x_end - runs.x_begin) * resolution;
    const double across_y = (runs.y_end - runs.y_begin) * resolution;
    // A gap is door-like when narrow one way and open the other way (the passage through it).
    const bool door_in_x = across_x >= 0.7 && across_x <= 1.3 && across_y >= 2.0;
    const bool door_in_y = across_y >= 0.7 && across_y <= 1.3 && across_x >= 2.0;
    const bool corridor_in_x = across_x >= 1.6 && across_x <= 3.0 && across_y >= 6.0;
    const bool corridor_in_y = across_y >= 1.6 && across_y <= 3.0 && across_x >= 6.0;
    geometry::Point centre = grid.cellCentre(cell.x, cell.y);
    double size_x = 0.0;
    double size_y = 0.0;
    bool door = false;
    if ((door_in_x || door_in_y) && doors < kDoorBoxes) {
      door = true;
      if (door_in_x) {
        centre.x() = grid.cornerToWorld(0.5 * (runs.x_begin + runs.x_end), 0.0).x();
        size_x = across_x - 0.1;
        size_y = 0.5;
      } else {
        centre.y() = grid.cornerToWorld(0.0, 0.5 * (runs.y_begin + runs.y_end)).y();
        size_x = 0.5;
        size_y = across_y - 0.1;
      }
    } else if ((corridor_in_x || corridor_in_y) && corridors < kCorridorBoxes) {
      // Against one side of the corridor, leaving at least 1.2 m beside it: a detour for the planners
      // that do not push, not a wall.
      const double across = corridor_in_x ? across_x : across_y;
      const double size = std::min(0.8, across - 1.3);
      if (size < 0.4) {
        continue;
      }
      size_x = size;
      size_y = size;
      const double side_offset = 0.1 + 0.5 * size;
      if (corridor_in_x) {
        centre.x() = grid.cornerToWorld(runs.x_begin, 0.0).x() + side_offset;
      } else {
        centre.y() = grid.cornerToWorld(0.0, runs.y_begin).y() + side_offset;
      }
    } else {
      continue;
    }
    const Box box{centre - geometry::Point(0.5 * size_x, 0.5 * size_y),
                  centre + geometry::Point(0.5 * size_x, 0.5 * size_y)};
    bool clear = boxFree(grid, box) && (centre - world.start.position()).norm() > 3.0;
    for (const geometry::Point& other : placed) {
      clear = clear && (centre - other).norm() > 4.0;
    }
    if (!clear) {
      continue;
    }
    const bool light = uniform(random, 0.0, 1.0) >= 0.2;
    world.objects.push_back(
        makeBox(static_cast<std::int64_t>(world.objects.size()) + 1, centre, size_x, size_y, light, random));
    placed.push_back(centre);
    (door ? doors : corridors) += 1;
  }
  world.source = map_yaml + " with " + std::to_string(doors) + " door and " + std::to_string(corridors) +
                 " corridor boxes (seed " + std::to_string(seed) + ")";
  return validated(std::move(world));
}

WorldSetResult scenarioWorlds(ScenarioKind kind, const WorldSetSettings& settings)
{
  WorldSetResult result;
  const auto add = [&result](const std::string& name, const sim::WorldResult& world, int quota) {
    if (!world.ok()) {
      result.error = world.error();
      return;
    }
    result.worlds.push_back(ScenarioWorld{name, world.world(), quota});
  };
  const int first_half = (settings.tasks + 1) / 2;
  const int second_half = settings.tasks - first_half;
  // Generated kinds take world seeds 2s-1 and 2s for suite seed s (offices 4s-1 .. 4s+2): suite seeds
  // never share a world, so a validation seed holds worlds the tuning seed never saw.
  const std::uint64_t seed = settings.seed;
  const std::uint64_t first_world = 2 * seed - 1;
  const auto generatedPair = [&](sim::WorldKind world_kind) {
    const std::string prefix = sim::worldKindName(world_kind);
    add(seeded(prefix, first_world), sim::generateWorld(world_kind, first_world), first_half);
    if (second_half > 0 && result.ok()) {
      add(seeded(prefix, first_world + 1), sim::generateWorld(world_kind, first_world + 1), second_half);
    }
  };
  switch (kind) {
    case ScenarioKind::Room:
      generatedPair(sim::WorldKind::Room);
      break;
    case ScenarioKind::RoomObjects:
      generatedPair(sim::WorldKind::RoomObjects);
      break;
    case ScenarioKind::Tunnel:
      generatedPair(sim::WorldKind::Tunnel);
      break;
    case ScenarioKind::BlockedOffice:
      generatedPair(sim::WorldKind::BlockedOffice);
      break;
    case ScenarioKind::BlockedTunnel:
      generatedPair(sim::WorldKind::BlockedTunnel);
      break;
    case ScenarioKind::Willow:
      if (fileExists(settings.willow_map)) {
        add("willow", willowWithObjects(settings.willow_map, seed), settings.tasks);
      } else {
        result.notes.push_back("willow map '" + settings.willow_map + "' absent: kind skipped");
      }
      break;
    case ScenarioKind::WillowPairs:
      if (fileExists(settings.willow_map)) {
        sim::WorldResult plain = sim::importGridMapFile(settings.willow_map, sim::GridImportSettings{});
        if (plain.ok()) {
          plain.world().name = "willow_full";
        }
        add("willow_full", plain, settings.tasks);
      } else {
        result.notes.push_back("willow map '" + settings.willow_map + "' absent: kind skipped");
      }
      break;
    case ScenarioKind::Namosim: {
      WorldSetResult namosim = namosimWorlds(settings.namosim_folder, settings.vehicle_width_m);
      result.worlds = std::move(namosim.worlds);
      result.notes.insert(result.notes.end(), namosim.notes.begin(), namosim.notes.end());
      result.error = namosim.error;
      break;
    }
    case ScenarioKind::Office:
      // Offices 4s-1 | 4s and 4s+1 | 4s+2.
      for (int pair = 0; pair < 2 && result.ok(); ++pair) {
        const int quota = pair == 0 ? first_half : second_half;
        if (quota <= 0) {
          break;
        }
        const std::uint64_t west_seed = 4 * seed - 1 + 2 * static_cast<std::uint64_t>(pair);
        const sim::WorldResult west = sim::generateWorld(sim::WorldKind::Office, west_seed);
        const sim::WorldResult east = sim::generateWorld(sim::WorldKind::Office, west_seed + 1);
        if (!west.ok() || !east.ok()) {
          result.error = west.ok() ? east.error() : west.error();
          break;
        }
        add("office2x-" + std::to_string(west_seed) + "+" + std::to_string(west_seed + 1),
            joinOfficesAlongCorridor(west.world(), east.world()), quota);
      }
      break;
  }
  if (!result.ok()) {
    result.worlds.clear();
  }
  return result;
}

}  // namespace ifar::scenarios
