#include "bench/scenarios/task_selection.hpp"

#include <cmath>
#include <random>

#include "bench/scenarios/task_lengths.hpp"
#include "sim/world/world_geometry.hpp"

namespace ifar::scenarios {
namespace {

constexpr auto kBlocked = grid_map::UnknownPolicy::AsBlocked;

/// The vehicle can stand at `point`: free on the planners' (inflated) grid, far enough from the static
/// obstacles and from every movable object.
bool standable(const sim::World& world, const ScenarioMaps& maps, const geometry::Point& point,
               double clearance)
{
  const grid_map::CellIndex cell = maps.planning_grid.cellAt(point);
  if (maps.planning_grid.blocked(cell.x, cell.y, kBlocked) || maps.exact.obstacles.isBlocked(point) ||
      maps.exact.obstacles.distanceToBoundary(point) < clearance) {
    return false;
  }
  for (const sim::MovableObject& object : world.objects) {
    const geometry::Polygon outline = sim::placedOutline(object);
    if (geometry::containsPoint(outline, point) || geometry::distanceToBoundary(outline, point) < clearance) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<Task> selectTasks(const sim::World& world, const ScenarioMaps& maps,
                              const TaskSelectionSettings& settings)
{
  std::vector<Task> tasks;
  if (settings.count <= 0) {
    return tasks;
  }
  graph::SearchScratch scratch;
  int passed_over = 0;
  const auto consider = [&](const geometry::Point& start, const geometry::Point& goal, bool from_world) {
    if (!standable(world, maps, start, settings.min_clearance_m) ||
        !standable(world, maps, goal, settings.min_clearance_m)) {
      return;
    }
    // The vehicle must fit from start to goal once every movable object is gone; whether objects too
    // heavy to push close the way is what reachable_with_pushing records (such a task stays in).
    const int component = vehicleComponent(maps, start);
    if (component < 0 || component != vehicleComponent(maps, goal)) {
      return;
    }
    const ExactOptimum optimum = exactOptimum(maps, start, goal, scratch);
    if (!std::isfinite(optimum.length) || optimum.length <= settings.min_optimal) {
      return;
    }
    Task task;
    task.start = start;
    task.start_heading = optimum.heading;
    task.goal = goal;
    task.optimal = optimum.length;
    task.achievable = lengthOn(maps.pushing, start, goal, scratch);
    task.without_pushing = lengthOn(maps.far, start, goal, scratch);
    task.reachable_with_pushing = std::isfinite(task.achievable);
    task.from_world = from_world;
    if (settings.require_achievable && !task.reachable_with_pushing) {
      return;
    }
    if (passed_over < settings.skip_first) {
      ++passed_over;
      return;
    }
    task.id = "t" + std::to_string(tasks.size());
    tasks.push_back(task);
  };
  if (settings.include_world_task) {
    for (const sim::Goal& goal : world.goals) {
      if (static_cast<int>(tasks.size()) < settings.count) {
        consider(world.start.position(), goal.position, true);
      }
    }
  }
  std::vector<grid_map::CellIndex> free_cells;
  const grid_map::GridMap& grid = maps.planning_grid;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (!grid.blocked(x, y, kBlocked)) {
        free_cells.push_back({x, y});
      }
    }
  }
  if (free_cells.empty()) {
    return tasks;
  }
  // Raw engine output modulo the count: std:: distributions differ between standard libraries.
  std::mt19937_64 random(settings.seed);
  for (int attempt = 0; attempt < settings.max_attempts && static_cast<int>(tasks.size()) < settings.count;
       ++attempt) {
    const grid_map::CellIndex a = free_cells[random() % free_cells.size()];
    const grid_map::CellIndex b = free_cells[random() % free_cells.size()];
    consider(grid.cellCentre(a.x, a.y), grid.cellCentre(b.x, b.y), false);
  }
  return tasks;
}

sim::World taskWorld(const sim::World& world, const Task& task)
{
  sim::World driven = world;
  driven.start = geometry::Pose2{task.start.x(), task.start.y(), task.start_heading};
  driven.goals = {sim::Goal{"task_" + task.id, task.goal}};
  sim::updateBounds(driven);
  return driven;
}

}  // namespace ifar::scenarios
