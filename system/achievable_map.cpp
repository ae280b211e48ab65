#include "system/achievable_map.hpp"

#include <limits>
#include <utility>

#include "common/grid_map/boundaries.hpp"
#include "planner/graph/visibility_builder.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_raster.hpp"

namespace ifar::runner {
namespace {

constexpr auto kBlocked = grid_map::UnknownPolicy::AsBlocked;

}  // namespace

PlanningGraph makePlanningGraph(std::vector<graph::ObstacleLoop> loops, const graph::Bounds& bounds)
{
  PlanningGraph result{
      graph::PriorMap{graph::ObstacleSet(std::move(loops), bounds), graph::DvGraph(), graph::BuildStats()},
      graph::SearchGraph()};
  result.map.stats = graph::addReducedVisibilityGraph(result.map.obstacles, result.map.graph);
  result.search = graph::SearchGraph::fromDvGraph(result.map.graph);
  return result;
}

std::vector<graph::ObstacleLoop> blockedLoops(const grid_map::GridMap& grid)
{
  std::vector<graph::ObstacleLoop> loops;
  for (geometry::Polygon& polygon : grid_map::blockedBoundaries(grid, kBlocked)) {
    loops.push_back(graph::ObstacleLoop{std::move(polygon), 0});
  }
  return loops;
}

graph::Bounds gridBounds(const grid_map::GridMap& grid)
{
  return graph::Bounds{grid.cornerToWorld(0, 0), grid.cornerToWorld(grid.width(), grid.height())};
}

geometry::Polygon inflatedObjectOutline(const sim::MovableObject& object, double radius)
{
  return interaction::dilateConvex(geometry::convexHull(sim::placedOutline(object)), radius);
}

PlanningGraph buildAchievableMap(const sim::World& world, const grid_map::GridMap& inflated_static,
                                 const common::VehicleSettings& vehicle, double inflation_m)
{
  std::vector<graph::ObstacleLoop> loops = blockedLoops(inflated_static);
  for (const sim::MovableObject& object : world.objects) {
    if (!sim::isPushable(object, vehicle)) {
      loops.push_back(graph::loopFromPolygon(inflatedObjectOutline(object, inflation_m), object.id));
    }
  }
  return makePlanningGraph(std::move(loops), gridBounds(inflated_static));
}

PlanningGraph buildAchievableMap(const sim::World& world, const common::VehicleSettings& vehicle,
                                 const AchievableMapSettings& settings)
{
  const grid_map::GridMap inflated_static =
      sim::rasterizeStaticObstacles(world, settings.resolution_m).inflated(settings.inflation_m, kBlocked);
  return buildAchievableMap(world, inflated_static, vehicle, settings.inflation_m);
}

double achievableDistance(const PlanningGraph& map, const geometry::Point& from, const geometry::Point& to,
                          graph::SearchScratch& scratch)
{
  const graph::SearchResult result = graph::findPath(map.search, map.map.obstacles, from, to, scratch);
  if (result.status != graph::SearchStatus::Found) {
    return std::numeric_limits<double>::infinity();
  }
  return (result.start - from).norm() + result.length + (to - result.goal).norm();
}

}  // namespace ifar::runner
