#pragma once
// How a driven run ended, as the status of its row: "arrived"; "no_path" when the planner had no path at
// the end (the runner's reason then carries "; planner: <why>"); for FAR mode "no_path_pushing_required"
// when, besides, the known map has no way that never pushes (the correct answer of a planner that may not
// push); "time_limit" when the simulated-time limit ended it with a path in hand; "failed" otherwise (the
// executive stopped).

#include <string>

namespace ifar::scenarios {

/// `reason`: the runner's RunSummary::reason; `without_pushing`: Task::without_pushing (NaN when every way
/// needs a push).
std::string drivenStatus(bool arrived, const std::string& reason, bool far_mode, double without_pushing);

/// True for a status that is the right verdict for its mode, arrival or not: "arrived" and
/// "no_path_pushing_required".
bool correctOutcome(const std::string& status);

}  // namespace ifar::scenarios
