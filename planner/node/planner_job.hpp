#pragma once
// One unit of planner work as the node hands it over: the latest revolution (or none: replan only), a goal
// change, and the executive's findings since the last job. The daemon runs jobs on its worker thread, the
// headless runner in line; both through runPlannerJob and toOutputs, so what they publish is the same.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ifar/dv_graph_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "planner/core/planner.hpp"

namespace ifar::planner {

struct PlannerJob {
  std::optional<FrameInput> frame;  // nullopt: replan only (a goal, an affordance or a passage changed)
  std::optional<Goal> new_goal;
  bool clear_goal = false;
  std::vector<AffordanceUpdate> affordances;     // applied first, in order
  std::vector<BlockedPassage> blocked_passages;  // then these, in order
};

struct PlannerJobResult {
  FrameResult result;
  std::string goal_problem;  // why a new goal was refused; empty when it was taken (or none came)
};

/// Applies the job to `planner`: goal change, affordances, blocked passages, then the frame (or a search
/// on the current graph). A library failure is reported in the result's status, never thrown.
PlannerJobResult runPlannerJob(Planner& planner, const PlannerJob& job);

/// What one finished job publishes (DV_GRAPH, GLOBAL_PATH, PLANNER_STATUS).
struct PlannerOutputs {
  std::optional<dv_graph_t> graph;  // built only when asked for: the headless runner has no use for it
  path_t path;
  planner_status_t status;
};

/// The messages of a finished job, stamped `now_utime`; a refused goal makes the status BAD_INPUT with the
/// reason first. Call on the thread that owns `planner`.
PlannerOutputs toOutputs(const Planner& planner, const PlannerJobResult& finished, std::int64_t now_utime,
                         bool with_graph);

}  // namespace ifar::planner
