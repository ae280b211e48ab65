#include "bench/scenarios/scenario_maps.hpp"

#include <chrono>
#include <utility>

#include "common/grid_map/boundaries.hpp"
#include "planner/graph/visibility_builder.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/graph_edges.hpp"
#include "planner/interaction/interaction_planner.hpp"
#include "sim/importers/grid_importer.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_raster.hpp"

namespace ifar::scenarios {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kBlocked = grid_map::UnknownPolicy::AsBlocked;

graph::PriorMap emptyMap()
{
  return graph::PriorMap{graph::ObstacleSet(std::vector<graph::ObstacleLoop>{}), graph::DvGraph(),
                         graph::BuildStats()};
}

/// Adds each splitting object's topological waypoints and interaction edges to `ours`.
InteractionStats addInteractions(const sim::World& world, const grid_map::GridMap& inflated_static,
                                 const std::vector<geometry::Polygon>& inflated_objects,
                                 const MapSettings& settings, PlanningGraph& ours,
                                 std::vector<interaction::PushPlan>& push_plans)
{
  const Clock::time_point began = Clock::now();
  InteractionStats stats;
  // The background as rectangles of blocked cells of the inflated static grid (what a local layer of
  // inflated polygons would hold), picked per object out to the planner's scene margin: cut off nearer
  // (it was the connectivity window + 1 m), free space ran round the onward check's edge and the check
  // passed pushes that close the way on.
  std::vector<geometry::Polygon> background;
  for (const sim::CellRectangle& cells : sim::blockedRectangles(inflated_static, kBlocked)) {
    const geometry::Point low = inflated_static.cornerToWorld(cells.x0, cells.y0);
    const geometry::Point high = inflated_static.cornerToWorld(cells.x1, cells.y1);
    background.push_back({low, geometry::Point(high.x(), low.y()), high, geometry::Point(low.x(), high.y())});
  }
  const double margin = interaction::sceneMargin(settings.interaction);
  for (std::size_t index = 0; index < world.objects.size(); ++index) {
    interaction::Bounds window = interaction::boundsOf(inflated_objects[index]);
    window.minimum -= geometry::Point(margin, margin);
    window.maximum += geometry::Point(margin, margin);
    interaction::LocalScene scene;
    for (const geometry::Polygon& polygon : background) {
      if (window.overlaps(interaction::boundsOf(polygon))) {
        scene.background.push_back(polygon);
      }
    }
    std::size_t movable_index = 0;
    for (std::size_t other = 0; other < world.objects.size(); ++other) {
      if (other == index) {
        movable_index = scene.movable.size();
      }
      if (other == index || window.overlaps(interaction::boundsOf(inflated_objects[other]))) {
        scene.movable.push_back(inflated_objects[other]);
      }
    }
    ++stats.objects;
    const interaction::ObjectInteractions interactions = interaction::planObjectInteractions(
        scene, movable_index, interaction::ObjectPhysics{}, settings.interaction);
    if (!interactions.connectivity.splits) {
      continue;
    }
    ++stats.splitting;
    const interaction::InsertedInteractions inserted = interaction::insertInteractions(
        ours.map.graph, world.objects[index].id, interactions, static_cast<std::uint32_t>(push_plans.size()));
    for (const interaction::PairPlan& pair : interactions.plans) {
      push_plans.push_back(pair.plan);
    }
    stats.edges += inserted.edges.size();
    for (const graph::VertexId waypoint : inserted.waypoint_vertices) {
      graph::connectByVisibility(ours.map.obstacles, ours.map.graph, waypoint);
    }
  }
  ours.search = graph::SearchGraph::fromDvGraph(ours.map.graph);
  stats.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - began).count();
  return stats;
}

/// Marks the cells the movable objects overlap as blocked (the grid covers the world's bounds).
void addObjects(const sim::World& world, grid_map::GridMap& grid)
{
  // Only the objects, over the same bounds, so the raster lines up with the static one cell for cell.
  sim::World objects_only;
  objects_only.bounds_min = world.bounds_min;
  objects_only.bounds_max = world.bounds_max;
  for (const sim::MovableObject& object : world.objects) {
    objects_only.obstacles.push_back(
        sim::StaticObstacle{object.name, sim::placedOutline(object), object.height_m, object.reflectivity});
  }
  const grid_map::GridMap objects = sim::rasterizeStaticObstacles(objects_only, grid.resolution());
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (objects.at(x, y) == grid_map::Cell::Blocked) {
        grid.set(x, y, grid_map::Cell::Blocked);
      }
    }
  }
}

/// 4-connected components of the free cells (4-connected: the exact polygons forbid squeezing between
/// cells that touch at a corner).
std::vector<int> freeComponents(const grid_map::GridMap& grid)
{
  const int width = grid.width();
  std::vector<int> labels(static_cast<std::size_t>(width) * static_cast<std::size_t>(grid.height()), -1);
  std::vector<int> stack;
  int next = 0;
  for (int start = 0; start < static_cast<int>(labels.size()); ++start) {
    if (labels[static_cast<std::size_t>(start)] >= 0 ||
        grid.blocked(start % width, start / width, kBlocked)) {
      continue;
    }
    labels[static_cast<std::size_t>(start)] = next;
    stack.push_back(start);
    while (!stack.empty()) {
      const int cell = stack.back();
      stack.pop_back();
      const int x = cell % width;
      const int y = cell / width;
      const int neighbours[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
      for (const auto& neighbour : neighbours) {
        if (!grid.contains(neighbour[0], neighbour[1]) ||
            grid.blocked(neighbour[0], neighbour[1], kBlocked)) {
          continue;
        }
        const auto index = static_cast<std::size_t>(neighbour[1]) * static_cast<std::size_t>(width) +
                           static_cast<std::size_t>(neighbour[0]);
        if (labels[index] < 0) {
          labels[index] = next;
          stack.push_back(static_cast<int>(index));
        }
      }
    }
    ++next;
  }
  return labels;
}

}  // namespace

int vehicleComponent(const ScenarioMaps& maps, const geometry::Point& point)
{
  const grid_map::CellIndex cell = maps.planning_grid.cellAt(point);
  if (!maps.planning_grid.contains(cell.x, cell.y) || maps.vehicle_components.empty()) {
    return -1;
  }
  return maps.vehicle_components[static_cast<std::size_t>(cell.y) *
                                     static_cast<std::size_t>(maps.planning_grid.width()) +
                                 static_cast<std::size_t>(cell.x)];
}

grid_map::GridMap rasterizeWorld(const sim::World& world, double resolution, bool with_objects)
{
  grid_map::GridMap grid = sim::rasterizeStaticObstacles(world, resolution);
  if (with_objects) {
    addObjects(world, grid);
  }
  return grid;
}

ScenarioMaps buildScenarioMaps(const sim::World& world, const MapSettings& settings)
{
  const Clock::time_point began = Clock::now();
  ScenarioMaps maps{rasterizeWorld(world, settings.resolution_m, false),
                    emptyMap(),
                    graph::SearchGraph(),
                    grid_map::GridMap(),
                    PlanningGraph{emptyMap(), graph::SearchGraph()},
                    PlanningGraph{emptyMap(), graph::SearchGraph()},
                    {},
                    PlanningGraph{emptyMap(), graph::SearchGraph()},
                    {},
                    InteractionStats{},
                    0.0};
  maps.exact = graph::buildPriorMap(maps.static_grid, 0.0, kBlocked);
  maps.exact_search = graph::SearchGraph::fromDvGraph(maps.exact.graph);
  maps.planning_grid =
      rasterizeWorld(world, settings.resolution_m, true).inflated(settings.inflation_m, kBlocked);

  const grid_map::GridMap inflated_static = maps.static_grid.inflated(settings.inflation_m, kBlocked);
  maps.vehicle_components = freeComponents(inflated_static);
  std::vector<graph::ObstacleLoop> all_loops = runner::blockedLoops(inflated_static);
  std::vector<geometry::Polygon> inflated_objects;
  for (const sim::MovableObject& object : world.objects) {
    inflated_objects.push_back(runner::inflatedObjectOutline(object, settings.inflation_m));
    all_loops.push_back(graph::loopFromPolygon(inflated_objects.back(), object.id));
  }
  maps.far = runner::makePlanningGraph(std::move(all_loops), runner::gridBounds(inflated_static));
  maps.pushing = runner::buildAchievableMap(world, inflated_static, settings.vehicle, settings.inflation_m);
  maps.ours = maps.far;
  maps.interaction =
      addInteractions(world, inflated_static, inflated_objects, settings, maps.ours, maps.push_plans);
  maps.build_seconds = std::chrono::duration<double>(Clock::now() - began).count();
  return maps;
}

}  // namespace ifar::scenarios
