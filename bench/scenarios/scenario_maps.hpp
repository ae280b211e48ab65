#pragma once
// Everything the planners of one world need, built once per world so every planner sees the same map:
//
// - ground truth: the static obstacles rasterised at `resolution_m` (a cell is blocked when it overlaps
//   an obstacle) and the exact zero-inflation visibility graph of its cell-boundary polygons, movable
//   objects removed;
// - the planners' map: static obstacles inflated by the vehicle's half width plus every movable object
//   (its outline grown by the same radius) as an obstacle. Grid A* gets it as a grid, RRT* and BIT* as
//   exact polygons, FAR mode as the reduced visibility graph of those polygons, ours as the same graph plus
//   the topological waypoints and interaction edges of every object that splits the free space;
// - reachability with pushing: the same map with only the objects too heavy for the vehicle.

#include <cstddef>
#include <vector>

#include "common/grid_map/grid_map.hpp"
#include "common/vehicle.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_plan.hpp"
#include "sim/world/world.hpp"
#include "system/achievable_map.hpp"

namespace ifar::scenarios {

struct MapSettings {
  double resolution_m = 0.15;
  double inflation_m = 0.35;  // the vehicle's half width
  common::VehicleSettings vehicle;
  interaction::InteractionSettings interaction;
};

using runner::PlanningGraph;

struct InteractionStats {
  std::size_t objects = 0;    // movable objects analysed
  std::size_t splitting = 0;  // objects that split the free space (got waypoints)
  std::size_t edges = 0;      // interaction edges added
  double milliseconds = 0.0;  // wall time of connectivity + push planning, all objects
};

struct ScenarioMaps {
  grid_map::GridMap static_grid;  // zero inflation, static obstacles only
  graph::PriorMap exact;          // ground truth on static_grid
  graph::SearchGraph exact_search;
  grid_map::GridMap planning_grid;                // static + movable, inflated: grid A*, start/goal checks
  PlanningGraph far;                              // static inflated + movable objects as obstacles
  PlanningGraph ours;                             // far + interaction edges
  std::vector<interaction::PushPlan> push_plans;  // handles of ours' interaction edges
  PlanningGraph pushing;  // static inflated + unpushable objects: reachable with pushing (achievable_map.hpp)
  // Where the vehicle fits with every movable object removed: per cell of planning_grid, the 4-connected
  // component of the inflated static grid's free space, -1 where blocked.
  std::vector<int> vehicle_components;
  InteractionStats interaction;
  double build_seconds = 0.0;
};

ScenarioMaps buildScenarioMaps(const sim::World& world, const MapSettings& settings);

/// Component of the cell holding `point` in maps.vehicle_components; -1 when blocked or off the grid.
int vehicleComponent(const ScenarioMaps& maps, const geometry::Point& point);

/// The grid the planners see as a grid: static obstacles plus movable objects, not inflated.
grid_map::GridMap rasterizeWorld(const sim::World& world, double resolution, bool with_objects);

}  // namespace ifar::scenarios
