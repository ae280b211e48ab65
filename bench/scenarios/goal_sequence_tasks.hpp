#pragma once
// The tasks of a world whose file gives a goal sequence (a namosim scenario): one task per goal, in order,
// each from where the one before ends (the world's start for the first, with the file's heading), in the
// world as the file has it. Every goal gives a task, whatever its length or clearance: these are the
// scenario's own goals, not drawn ones. A goal no vehicle reaches even with pushing stays in, marked
// unreachable.

#include <vector>

#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/task_selection.hpp"
#include "sim/world/world.hpp"

namespace ifar::scenarios {

/// Ids "g0", "g1", ... in the world's goal order. A goal the known-map search has to move by more than
/// `goal_tolerance_m` (the executive's: the goal counts as reached within it) is not reached that way:
/// under a movable object, only pushing reaches it (without_pushing NaN).
std::vector<Task> goalSequenceTasks(const sim::World& world, const ScenarioMaps& maps,
                                    double goal_tolerance_m);

}  // namespace ifar::scenarios
