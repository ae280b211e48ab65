#pragma once
// The tasks of one world: start and goal in free space (the vehicle fits there: clear of the inflated
// static obstacles and of every movable object), connected for the vehicle once the movable objects are
// removed (so only objects can stand in the way), whose ground-truth optimal length exceeds the kind's
// threshold. The world's own start -> goal comes first when it qualifies, then seeded random pairs.
// Deterministic: the same world, maps and settings give the same tasks on every platform.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bench/scenarios/scenario_maps.hpp"
#include "common/geometry/point.hpp"
#include "sim/world/world.hpp"

namespace ifar::scenarios {

struct Task {
  std::string id;  // "t0", "t1", ... within the world
  geometry::Point start = geometry::Point::Zero();
  double start_heading = 0.0;  // along the first leg of the optimal path
  geometry::Point goal = geometry::Point::Zero();
  double optimal = 0.0;                // exact, zero inflation, movable objects removed
  bool reachable_with_pushing = true;  // false: only objects too heavy to push leave no route
  /// What a vehicle that knew the map could drive: the shortest path with the static obstacles inflated
  /// by its half width and the objects too heavy to push as obstacles (pushing the others for free).
  /// NaN when not reachable with pushing. Not the ground truth (`optimal`); a reference for why
  /// driven SPL falls short of it.
  double achievable = 0.0;
  /// The same with every movable object as an obstacle: what a vehicle that knew the map but never
  /// pushed could drive. NaN when objects close every way. 1 - achievable / without_pushing is the most
  /// pushing can save on the task.
  double without_pushing = 0.0;
  bool from_world = false;  // the world's own start -> goal

  /// The length a run's time budget is given for: the achievable way where it is known and longer than
  /// the exact optimum (a point's optimum can squeeze through gaps narrower than the vehicle, and the
  /// vehicle has to drive round), else the optimum.
  double budgetLength() const
  {
    return std::isfinite(achievable) && achievable > optimal ? achievable : optimal;
  }
};

struct TaskSelectionSettings {
  int count = 10;
  std::uint64_t seed = 1;
  double min_optimal = 15.0;  // strictly longer than this
  double min_clearance_m =
      0.6;  // start/goal this far from static obstacles and objects (vehicle half diagonal)
  int max_attempts = 20000;
  bool include_world_task = true;
  /// Pairs with no achievable way (objects too heavy to push close it) are left out, not kept as
  /// unreachable.
  bool require_achievable = false;
  /// The first this many pairs that qualify are passed over: one stream of pairs can be shared out in
  /// disjoint blocks (clear_pairs.hpp).
  int skip_first = 0;
};

std::vector<Task> selectTasks(const sim::World& world, const ScenarioMaps& maps,
                              const TaskSelectionSettings& settings);

/// `world` with the task's start (and heading) and its goal as the only goal: what the runner drives.
sim::World taskWorld(const sim::World& world, const Task& task);

}  // namespace ifar::scenarios
