#pragma once
// A PNG of a finished run: the world as ifar-render draws it (start pose and object poses at the
// start), the vehicle's ground-truth trajectory, the objects where they ended up, the goal and the
// outcome in the legend band.

#include <string>

#include "common/geometry/point.hpp"
#include "common/vehicle.hpp"
#include "sim/world/world.hpp"
#include "system/scenario_runner.hpp"

namespace ifar::runner {

/// Writes the picture to `path`. Returns an empty string on success, else the error naming the path.
std::string writeRunPicture(const sim::World& world, const common::VehicleSettings& vehicle,
                            const geometry::Point& goal, const RunSummary& summary, const std::string& path);

}  // namespace ifar::runner
