#pragma once
// The worlds of the namosim kind: every scenario SVG (*.svg) of a folder, read by the importer `ifar run`
// uses (sim/importers), scaled so the drawn robot is as wide as the vehicle. A file with several robots
// gives one world per robot that has goals, that robot the vehicle (the others are not simulated, as in
// `ifar run --robot`); a world's goals are its robot's goal sequence.

#include <string>

#include "bench/scenarios/scenario_worlds.hpp"

namespace ifar::scenarios {

/// Worlds named after the file ("two_rooms"), with "-<robot id>" after it when the file has more than one
/// robot with goals; task_quota is the goal count. Files in name order. A missing folder or one without
/// an SVG is a note (the kind is skipped), not an error; a file that does not import is a note naming it
/// and its error (the other files still count), as are the importer's warnings. A file the importer calls
/// incomplete (no walls, no drawn robot, no goals) gives no world, only a note with the importer's reasons.
WorldSetResult namosimWorlds(const std::string& folder, double vehicle_width_m);

}  // namespace ifar::scenarios
