// Built when the headless runner (system/, target ifar_runner) exists: Tables II and III for real.
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench/scenarios/system_runs.hpp"
#include "system/run_config.hpp"
#include "system/scenario_runner.hpp"

namespace ifar::scenarios {

bool systemRunnerAvailable()
{
  return true;
}

std::vector<std::string> sensingProfileNames()
{
  return runner::sensingProfileNames();
}

struct SystemRunner::Settings {
  std::map<std::string, runner::RunRequest> requests;  // per sensing profile: all but world, goal, mode, cap
};

SystemRunner::SystemRunner(const std::string& config_dir, const std::vector<std::string>& sensing_profiles)
{
  Settings settings;
  try {
    for (const std::string& sensing : sensing_profiles) {
      settings.requests.emplace(sensing, runner::loadRunSettings(config_dir, sensing));
    }
  } catch (const std::exception& error) {
    throw std::runtime_error(std::string("runner settings: ") + error.what());
  }
  settings_ = std::make_unique<const Settings>(std::move(settings));
}

SystemRunner::~SystemRunner() = default;

std::uint64_t SystemRunner::configuredSensingSeed() const
{
  return settings_->requests.empty() ? 1 : settings_->requests.begin()->second.sim.simulator.seed;
}

bool SystemRunner::drawsFromSeed(const std::string& sensing) const
{
  const auto settings = settings_->requests.find(sensing);
  return settings != settings_->requests.end() && settings->second.sim.simulator.sensing.drawsRandomNumbers();
}

SystemRun SystemRunner::run(const sim::World& world, const Task& task, bool interaction_enabled,
                            const std::string& sensing, std::optional<std::uint64_t> sensing_seed,
                            double max_sim_time_s) const
{
  SystemRun run;
  const auto settings = settings_->requests.find(sensing);
  if (settings == settings_->requests.end()) {
    run.reason = "no settings read for the sensing profile '" + sensing + "'";
    return run;
  }
  runner::RunRequest request = settings->second;
  request.world = taskWorld(world, task);
  request.goal = task.goal;
  request.planner.interaction_enabled = interaction_enabled;
  request.max_sim_time_s = max_sim_time_s;
  if (sensing_seed) {
    request.sim.simulator.seed = *sensing_seed;
  }
  run.ran = true;
  try {
    const runner::RunSummary summary = runner::runScenario(request, {});
    run.arrived = summary.arrived;
    run.reason = summary.reason;
    run.distance_m = summary.distance_m;
    run.sim_time_s = summary.sim_time_s;
    run.wall_time_s = summary.wall_time_s;
    run.pushes = summary.pushes;
    run.frame_median_ms = summary.planner_frame.median_ms;  // NaN when no frame was timed
    run.frame_p99_ms = summary.planner_frame.p99_ms;
    run.frame_max_ms = summary.planner_frame.max_ms;
    run.interaction_max_ms = summary.interaction.max_ms;
    run.undecided_saturated_pushes = summary.undecided_saturated_pushes;
    run.escalations = summary.escalations;
    if (summary.losses.valid) {
      run.excess_m = summary.losses.excess_m;
      run.losses = summary.losses.buckets;
    }
    // One pose per control cycle is more than a plot needs: keep one in ten.
    for (std::size_t index = 0; index < summary.trajectory.size(); index += 10) {
      run.trajectory.push_back(summary.trajectory[index]);
    }
    if (!summary.trajectory.empty()) {
      run.trajectory.push_back(summary.trajectory.back());
    }
  } catch (const std::exception& error) {
    run.arrived = false;
    run.failure_status = "error";
    run.reason = std::string("runner threw: ") + error.what();
  }
  return run;
}

}  // namespace ifar::scenarios
