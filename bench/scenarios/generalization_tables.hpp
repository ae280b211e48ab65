#pragma once
// The generalization suite's tables and targets: the driven runs of the kinds built from worlds nobody here
// made (namosim, willow_pairs), scored against what a vehicle that knew the map could do.

#include <string>
#include <vector>

#include "bench/scenarios/result_row.hpp"

namespace ifar::scenarios {

/// Per kind, mode and sensing profile: runs, arrivals, arrivals among the goals a pushing vehicle can reach,
/// SPL against the achievable length and the exact optimum, and how the other runs ended
/// (driven_outcome.hpp); then a row per namosim goal and one per willow_pairs run that did not arrive.
/// Empty when there is no driven row of these kinds.
std::string tableGeneralization(const std::vector<ResultRow>& rows);

/// Target lines ("| target | measured | verdict |" rows, no header) for the same kinds; empty when there is
/// no driven row of them.
std::string generalizationTargets(const std::vector<ResultRow>& rows);

}  // namespace ifar::scenarios
