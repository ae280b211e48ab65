#pragma once
// The planner's path as the executive reads it, without LCM: the same conversion the two daemons make
// through path_t (planner side: waypoint kinds and push plans; executive side: fromMessage), done in one
// step for the headless runner.

#include <cstdint>

#include "executive/modes/inputs.hpp"
#include "executive/pusher/push_plan.hpp"
#include "planner/core/planner.hpp"
#include "planner/graph/dv_graph.hpp"

namespace ifar::runner {

/// One push plan in the executive's terms. Straight and arc controls become pushes, contact switches
/// become SwitchContact; J is the plan's cost and travel its approach and switch distance; each control's
/// expected object heading is the change since the plan's start pose (as in push_control_t).
executive::PushPlan toExecutivePushPlan(const planner::PathPush& push);

/// Waypoint kinds as the planner daemon writes path_t: the waypoint a push reaches is Push (with the
/// object id and its plan index), a waypoint on a topological graph vertex is Topological (where a push
/// starts, the executive takes the plan of the Push waypoint after it), the rest Free. Push plans keep
/// the order of `path.pushes`. `graph` is the planner's global graph the path was searched on (for vertex
/// kinds); `utime` and `sequence` stamp the plan as the planner daemon would.
executive::Path toExecutivePath(const planner::PlannedPath& path, const graph::DvGraph& graph,
                                std::int64_t utime, std::int64_t sequence);

}  // namespace ifar::runner
