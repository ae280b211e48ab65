#pragma once
// PNG plots of the evaluation through the repo's canvas (tools/render): search time against graph size
// per planner, and per kind the paths of ours against FAR mode drawn over the world.

#include <string>
#include <vector>

#include "bench/scenarios/result_row.hpp"
#include "common/geometry/point.hpp"
#include "sim/world/world.hpp"

namespace ifar::scenarios {

/// Log-log scatter: x = DV-graph vertices of the world's planning map (FAR mode's graph), y = CPU ms
/// per successful query, one colour per planner. Returns an empty string or the error.
std::string writeTimeVsGraphSizePlot(const std::vector<ResultRow>& rows, const std::string& path);

struct PathPair {
  std::vector<geometry::Point> far;
  std::vector<geometry::Point> ours;
  geometry::Point start = geometry::Point::Zero();
  geometry::Point goal = geometry::Point::Zero();
};

/// The world (static obstacles grey, light objects orange, heavy ones dark red) with FAR mode's path
/// (blue) and ours (green) per task, start (black dot) and goal (ring). `what` names the kind of line
/// ("planned paths" or "driven trajectories") in the title.
std::string writePathPlot(const sim::World& world, const std::vector<PathPair>& paths,
                          const std::string& title, const std::string& path);

/// Stacked bars of the loss accounting of one kind's driven runs: one bar per planner (FAR mode, ours)
/// and sensing profile, the mean metres per run of each bucket stacked (negative ones below the axis),
/// the mean excess marked. Writes nothing and returns an empty string when no run of the kind was
/// accounted; otherwise an empty string or the error.
std::string writeLossPlot(const std::vector<ResultRow>& rows, const std::string& kind,
                          const std::string& path);

}  // namespace ifar::scenarios
