#pragma once
// A run summary as one line of JSON, the last line `ifar run --json` prints:
// {"arrived":true,"reason":"arrived","distance_m":23.41,"time_s":41.2,"pushes":1,"replans":0,
//  "affordance_updates":0,"blocked_passages":0,"escalations":0,"goal_distance_m":0.42,"wall_time_s":12.3,
//  "planner_frame_ms":{"frames":103,"median":4.1,"p99":9.8,"max":12.0},"interaction_ms":{...}}

#include <string>

#include "system/scenario_runner.hpp"

namespace ifar::runner {

/// One JSON object on one line (no trailing newline); the trajectory is left out.
std::string summaryJson(const RunSummary& summary);

}  // namespace ifar::runner
