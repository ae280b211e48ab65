// Built when the headless runner (sim/runner, target ifar_runner) exists: Tables II and III for real.
#include <exception>

#include "bench/scenarios/system_runs.hpp"
#include "sim/runner/run_config.hpp"
#include "sim/runner/scenario_runner.hpp"

namespace ifar::scenarios {

bool systemRunnerAvailable()
{
  return true;
}

SystemRun runSystem(const sim::World& world, const Task& task, bool interaction_enabled,
                    const SystemRunSettings& settings)
{
  SystemRun run;
  runner::RunRequest request;
  try {
    request = runner::loadRunSettings(settings.config_dir);
  } catch (const std::exception& error) {
    run.reason = std::string("runner settings: ") + error.what();
    return run;
  }
  request.world = taskWorld(world, task);
  request.goal = task.goal;
  request.planner.interaction_enabled = interaction_enabled;
  request.max_sim_time_s = settings.max_sim_time_s;
  run.ran = true;
  try {
    const runner::RunSummary summary = runner::runScenario(request, {});
    run.arrived = summary.arrived;
    run.reason = summary.reason;
    run.distance_m = summary.distance_m;
    run.sim_time_s = summary.sim_time_s;
    run.wall_time_s = summary.wall_time_s;
    run.pushes = summary.pushes;
    // One pose per control cycle is more than a plot needs: keep one in ten.
    for (std::size_t index = 0; index < summary.trajectory.size(); index += 10) {
      run.trajectory.push_back(summary.trajectory[index]);
    }
    if (!summary.trajectory.empty()) {
      run.trajectory.push_back(summary.trajectory.back());
    }
  } catch (const std::exception& error) {
    run.arrived = false;
    run.reason = std::string("runner threw: ") + error.what();
  }
  return run;
}

}  // namespace ifar::scenarios
