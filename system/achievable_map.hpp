#pragma once
// The map a vehicle that knew the world could drive: static obstacles rasterised and inflated by the
// vehicle's half width, objects too heavy for it to push as obstacles, lighter objects left out (they
// can be pushed aside). The shortest way on it is a driven run's yardstick: the benchmark's "achievable"
// length and the loss accounting's distance to the goal (loss_accounting.hpp) both come from here.

#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"
#include "common/grid_map/grid_map.hpp"
#include "common/vehicle.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "sim/world/world.hpp"

namespace ifar::runner {

/// A visibility graph with the obstacles it was built against and its search snapshot.
struct PlanningGraph {
  graph::PriorMap map;  // obstacles + graph
  graph::SearchGraph search;
};

/// The reduced visibility graph of `loops` within `bounds`.
PlanningGraph makePlanningGraph(std::vector<graph::ObstacleLoop> loops, const graph::Bounds& bounds);

/// The outlines of the blocked cells of `grid` (unknown cells count as blocked) as obstacle loops.
std::vector<graph::ObstacleLoop> blockedLoops(const grid_map::GridMap& grid);

/// The extent of `grid` in the world.
graph::Bounds gridBounds(const grid_map::GridMap& grid);

/// The object's outline in the world grown by `radius` (convex hull, mitred corners).
geometry::Polygon inflatedObjectOutline(const sim::MovableObject& object, double radius);

struct AchievableMapSettings {
  double resolution_m = 0.15;  // raster of the static obstacles
  double inflation_m = 0.35;   // the vehicle's half width
};

/// The achievable map on an already inflated static grid (`inflated_static`: the static obstacles
/// rasterised at the settings' resolution and inflated by inflation_m).
PlanningGraph buildAchievableMap(const sim::World& world, const grid_map::GridMap& inflated_static,
                                 const common::VehicleSettings& vehicle, double inflation_m);
/// The same from the world alone.
PlanningGraph buildAchievableMap(const sim::World& world, const common::VehicleSettings& vehicle,
                                 const AchievableMapSettings& settings);

/// Length of the shortest way on `map` from `from` to `to`, infinity when there is none. A point inside
/// an inflated obstacle (the raster's cells reach up to a cell beyond the true outline, so a vehicle
/// grazing a wall stands in one now and then) is moved to the nearest free point and the move counts.
double achievableDistance(const PlanningGraph& map, const geometry::Point& from, const geometry::Point& to,
                          graph::SearchScratch& scratch);

}  // namespace ifar::runner
