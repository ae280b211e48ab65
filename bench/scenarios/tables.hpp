#pragma once
// The paper's three tables as Markdown from the result rows, plus the issue 8 targets checked against
// them. Percentiles are nearest-rank over the successful queries (the paper averages successful searches
// only); every cell says how many of the tasks succeeded.

#include <optional>
#include <string>
#include <vector>

#include "bench/scenarios/result_row.hpp"
#include "bench/scenarios/sim_time_budget.hpp"

namespace ifar::scenarios {

std::string tableOneSearchTime(const std::vector<ResultRow>& rows);
/// With `stricter`, the driven rows again counting only the arrivals within that budget (the same runs:
/// a run is deterministic in simulated time, so one that arrived within it would have under it).
std::string tableTwoSpl(const std::vector<ResultRow>& rows,
                        const std::optional<SimTimeBudget>& stricter = std::nullopt);
std::string tableThreeSystem(const std::vector<ResultRow>& rows);
/// The planner's frame times in the driven runs, per kind: the median of the runs' medians, the worst
/// run's p99, the longest frame, and the longest interaction stage alone (the runner lifts the daemon's
/// frame budget, so this is all the work one frame asked for). `parallel_runs`: how many runs shared the
/// machine at a time (--jobs), said in the caption since wall times depend on it.
std::string tablePlannerFrames(const std::vector<ResultRow>& rows, int parallel_runs);
/// Per kind, the distance the driven runs travelled beyond the achievable way and its buckets
/// (system/loss_accounting.hpp), metres per run, per planner and sensing profile; and the largest gap
/// between a row's buckets and its excess (they add up by construction).
std::string tableLosses(const std::vector<ResultRow>& rows);
/// The targets with the measured value and whether it is met (or by how much it is missed).
std::string targetCheck(const std::vector<ResultRow>& rows);

}  // namespace ifar::scenarios
