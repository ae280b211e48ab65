#pragma once
// One row of the evaluation: a planner on one task, as the JSON line written to
// bench/results/latest.jsonl, and SPL (Anderson et al. 2018).

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "system/loss_accounting.hpp"

namespace ifar::scenarios {

struct ResultRow {
  std::string table;    // "search" (Tables I and II, planned paths) or "system" (Tables II and III, runner)
  std::string planner;  // grid_astar, rrt_star, bit_star, far, ours
  std::string kind;     // room, room_objects, office, tunnel
  std::string world;    // e.g. "tunnel-1"
  std::string task;     // e.g. "t3"
  bool success = false;
  double length = 0.0;      // planned path (search) or travelled distance (system), metres; NaN when none
  double optimal = 0.0;     // ground truth, metres
  double achievable = NAN;  // Task::achievable: inflated, unpushable objects as obstacles; NaN: unknown
  double without_pushing = NAN;  // Task::without_pushing: inflated, every object as an obstacle
  double ms = 0.0;              // search: planner-thread CPU ms; system: wall ms of the run; NaN when not run
  std::string status;           // solved, no_path, timeout, error, unreachable, runner_unavailable, ...
  std::string reason;           // why it failed; empty on success
  double graph_vertices = 0.0;  // size of the map the planner searched (DV-graph vertices; grid: cells)
  double sim_time_s = 0.0;      // system rows: simulated time to the end of the run
  int pushes = 0;               // system rows: pushes executed
  // System rows: the runner's planner frames, wall ms (two runs share the machine's cores), and the
  // most one frame's interaction planning took without the daemon's frame budget. NaN when not run.
  double frame_median_ms = NAN;
  double frame_p99_ms = NAN;
  double frame_max_ms = NAN;
  double interaction_max_ms = NAN;
  // System rows: the simulator's sensing profile (sim.yaml sensing:, "ideal" or "field"), and the pushes
  // held at maximum force past the tactile monitor's window without a decision (runner::RunSummary).
  std::string sensing = "ideal";
  int sensing_seed = 1;  // the seed the sensor models drew from (sim.yaml's, or the bench's --sensing-seeds)
  int undecided_saturated_pushes = 0;
  int escalations = 0;  // system rows: the progress monitor's escalations (runner::RunSummary)
  // System rows: the distance driven beyond the achievable way (travelled - (achievable - left at the
  // end)) and where it went (system/loss_accounting.hpp); NaN when not accounted.
  double excess_m = NAN;
  runner::LossBuckets losses = runner::notAccounted();
};

/// Success weighted by path length for one episode: success x optimal / max(length, optimal); 0 for a
/// failure, an unknown length or a non-positive optimum.
double successWeightedByPathLength(bool success, double optimal, double length);

/// The sensing profiles of the system rows, "ideal" first, then in the order they appear (empty: none).
std::vector<std::string> sensingProfiles(const std::vector<ResultRow>& rows);

/// The row as one JSON object on one line (no trailing newline). Keys in a fixed order; non-finite
/// numbers are written as null; strings escaped per RFC 8259.
std::string toJsonLine(const ResultRow& row);

/// Every field of the row as a child process's answer (answer_text.hpp), and back: exact, NaN included.
/// nullopt when `answer` is not such an answer.
std::string toAnswer(const ResultRow& row);
std::optional<ResultRow> rowFromAnswer(std::string_view answer);

}  // namespace ifar::scenarios
