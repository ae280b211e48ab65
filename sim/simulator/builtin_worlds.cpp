#include "sim/simulator/builtin_worlds.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace ifar::sim {
namespace {

geometry::Polygon rectangle(double low_x, double low_y, double high_x, double high_y)
{
  return {geometry::Point(low_x, low_y), geometry::Point(high_x, low_y), geometry::Point(high_x, high_y),
          geometry::Point(low_x, high_y)};
}

StaticObstacle wall(const std::string& name, double low_x, double low_y, double high_x, double high_y,
                    double height_m)
{
  StaticObstacle obstacle;
  obstacle.name = name;
  obstacle.outline = rectangle(low_x, low_y, high_x, high_y);
  obstacle.height_m = height_m;
  obstacle.reflectivity = 0.2;
  return obstacle;
}

// Row-major index of a maze cell, computed in std::size_t so a large maze cannot overflow int.
std::size_t mazeCellIndex(int column, int row, int columns)
{
  return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(column);
}

void addBoundary(World& world, double width, double height, double thickness, double wall_height)
{
  world.obstacles.push_back(wall("wall_south", 0.0, 0.0, width, thickness, wall_height));
  world.obstacles.push_back(wall("wall_north", 0.0, height - thickness, width, height, wall_height));
  world.obstacles.push_back(wall("wall_west", 0.0, thickness, thickness, height - thickness, wall_height));
  world.obstacles.push_back(
      wall("wall_east", width - thickness, thickness, width, height - thickness, wall_height));
  world.bounds_min = geometry::Point(0.0, 0.0);
  world.bounds_max = geometry::Point(width, height);
}

/// splitmix64: a tiny generator whose output is the same on every platform (std distributions are not).
class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next()
  {
    std::uint64_t value = (state_ += 0x9E3779B97F4A7C15ULL);
    value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
    value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
    return value ^ (value >> 31);
  }
  std::size_t below(std::size_t bound) { return static_cast<std::size_t>(next() % bound); }

 private:
  std::uint64_t state_;
};

}  // namespace

World builtinRoom(double size_m)
{
  World world;
  world.name = "builtin_room";
  world.source = "builtin:room";
  addBoundary(world, size_m, size_m, 0.2, 2.0);
  world.start = geometry::Pose2{2.0, 0.5 * size_m, 0.0};
  world.goals.push_back({"far_side", geometry::Point(size_m - 2.0, 0.5 * size_m)});
  return world;
}

World builtinPushRoom(double box_mass_kg, double box_friction, double box_side_m, double box_distance_m,
                      double room_size_m)
{
  World world = builtinRoom(room_size_m);
  world.name = "builtin_push_room";
  world.source = "builtin:push";
  MovableObject box;
  box.id = 1;
  box.name = "box";
  const double half = 0.5 * box_side_m;
  box.outline = rectangle(-half, -half, half, half);
  box.pose = geometry::Pose2{world.start.x + box_distance_m, world.start.y, 0.0};
  box.height_m = 0.8;
  box.mass_kg = box_mass_kg;
  box.ground_friction = box_friction;
  box.reflectivity = 0.9;
  world.objects.push_back(box);
  return world;
}

World builtinTunnelNetwork(std::uint64_t seed, double width_m, double height_m, double corridor_m)
{
  World world;
  world.name = "builtin_tunnel";
  world.source = "builtin:tunnel";
  constexpr double kThickness = 0.3;
  constexpr double kHeight = 3.0;
  addBoundary(world, width_m, height_m, kThickness, kHeight);
  const int columns = std::max(1, static_cast<int>(width_m / corridor_m));
  const int rows = std::max(1, static_cast<int>(height_m / corridor_m));
  const double cell_width = width_m / columns;
  const double cell_height = height_m / rows;
  // A maze by randomized depth-first carving: open_east/open_north mark removed walls.
  const auto cell_count = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
  std::vector<bool> visited(cell_count, false);
  std::vector<bool> open_east(cell_count, false);
  std::vector<bool> open_north(cell_count, false);
  SplitMix random(seed);
  std::vector<std::pair<int, int>> stack{{0, 0}};
  visited[0] = true;
  while (!stack.empty()) {
    const auto [column, row] = stack.back();
    std::vector<std::pair<int, int>> neighbours;
    const std::pair<int, int> moves[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& [dx, dy] : moves) {
      const int next_column = column + dx;
      const int next_row = row + dy;
      if (next_column >= 0 && next_column < columns && next_row >= 0 && next_row < rows &&
          !visited[mazeCellIndex(next_column, next_row, columns)]) {
        neighbours.emplace_back(next_column, next_row);
      }
    }
    if (neighbours.empty()) {
      stack.pop_back();
      continue;
    }
    const auto [next_column, next_row] = neighbours[random.below(neighbours.size())];
    const int low_column = std::min(column, next_column);
    const int low_row = std::min(row, next_row);
    const auto low_index = mazeCellIndex(low_column, low_row, columns);
    if (next_column != column) {
      open_east[low_index] = true;
    } else {
      open_north[low_index] = true;
    }
    visited[mazeCellIndex(next_column, next_row, columns)] = true;
    stack.emplace_back(next_column, next_row);
  }
  // Some extra openings make loops, as a real tunnel network has.
  for (std::size_t index = 0; index < cell_count; ++index) {
    if (random.below(6) == 0) {
      open_east[index] = true;
    }
  }
  int wall_number = 0;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const auto index = mazeCellIndex(column, row, columns);
      const double x = column * cell_width;
      const double y = row * cell_height;
      if (column + 1 < columns && !open_east[index]) {
        world.obstacles.push_back(
            wall("wall_" + std::to_string(wall_number++), x + cell_width - kThickness / 2, y + kThickness / 2,
                 x + cell_width + kThickness / 2, y + cell_height - kThickness / 2, kHeight));
      }
      if (row + 1 < rows && !open_north[index]) {
        world.obstacles.push_back(wall("wall_" + std::to_string(wall_number++), x + kThickness / 2,
                                       y + cell_height - kThickness / 2, x + cell_width - kThickness / 2,
                                       y + cell_height + kThickness / 2, kHeight));
      }
    }
  }
  world.start = geometry::Pose2{0.5 * cell_width, 0.5 * cell_height, 0.0};
  world.goals.push_back(
      {"far_corner", geometry::Point(width_m - 0.5 * cell_width, height_m - 0.5 * cell_height)});
  return world;
}

bool builtinWorldByName(const std::string& name, World& world)
{
  if (name == "room") {
    world = builtinRoom();
  } else if (name == "push_light") {
    world = builtinPushRoom(20.0);
  } else if (name == "push_heavy") {
    world = builtinPushRoom(200.0);
  } else if (name == "tunnel") {
    world = builtinTunnelNetwork();
  } else {
    return false;
  }
  return true;
}

}  // namespace ifar::sim
