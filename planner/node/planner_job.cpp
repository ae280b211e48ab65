#include "planner/node/planner_job.hpp"

#include <exception>
#include <utility>

#include "planner/node/planner_messages.hpp"

namespace ifar::planner {

PlannerJobResult runPlannerJob(Planner& planner, const PlannerJob& job)
{
  PlannerJobResult finished;
  if (job.clear_goal) {
    planner.clearGoal();
  }
  if (job.new_goal && !planner.setGoal(*job.new_goal)) {
    finished.goal_problem =
        "goal " + std::to_string(job.new_goal->id) + " refused: coordinates are not finite";
  }
  try {
    std::optional<FrameResult> update_result;
    for (const AffordanceUpdate& update : job.affordances) {
      update_result = planner.applyAffordance(update);
    }
    for (const BlockedPassage& passage : job.blocked_passages) {
      update_result = planner.applyBlockedPassage(passage);
    }
    if (job.frame) {
      finished.result = planner.processFrame(*job.frame);
    } else if (update_result && !job.new_goal && !job.clear_goal) {
      finished.result = std::move(*update_result);  // already searched again
    } else {
      finished.result = planner.replan();
    }
  } catch (const std::exception& error) {
    // A library failure costs this update, never the process: reported like rejected input.
    finished.result = FrameResult{};
    finished.result.status.state = PlannerState::BadInput;
    finished.result.status.message = std::string("planner update failed: ") + error.what();
  }
  return finished;
}

PlannerOutputs toOutputs(const Planner& planner, const PlannerJobResult& finished, std::int64_t now_utime,
                         bool with_graph)
{
  PlannerOutputs outputs;
  if (with_graph) {
    outputs.graph = toGraphMessage(planner, finished.result);
  }
  outputs.path = toPathMessage(planner.graph(), finished.result, now_utime);
  outputs.status = toStatusMessage(finished.result.status);
  if (!finished.goal_problem.empty()) {
    outputs.status.state = planner_status_t::STATE_BAD_INPUT;
    outputs.status.message =
        finished.goal_problem + (outputs.status.message.empty() ? "" : "; " + outputs.status.message);
  }
  return outputs;
}

}  // namespace ifar::planner
