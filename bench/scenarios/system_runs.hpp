#pragma once
// Tables II and III (system level): the headless runner (sim/runner, contract C) drives the vehicle
// through a task with FAR mode or ours. CMake builds this against the runner when the ifar_runner target
// exists (system_runs_runner.cpp) and otherwise against a stand-in that reports "runner unavailable"
// (system_runs_unavailable.cpp), so Tables II and III always come out of the same command.

#include <string>
#include <vector>

#include "bench/scenarios/task_selection.hpp"
#include "common/geometry/pose2.hpp"
#include "sim/world/world.hpp"

namespace ifar::scenarios {

struct SystemRunSettings {
  std::string config_dir;         // holds vehicle.yaml, sim.yaml, planner.yaml, executive.yaml
  double max_sim_time_s = 600.0;  // per run
};

struct SystemRun {
  bool ran = false;  // false: the runner is not available (or refused the request); see `reason`
  bool arrived = false;
  std::string reason;
  double distance_m = 0.0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  int pushes = 0;
  std::vector<geometry::Pose2> trajectory;
};

/// False when this build has no headless runner.
bool systemRunnerAvailable();

/// Drives from task.start to task.goal in `world` (its start and goals replaced by the task's).
/// `interaction_enabled` false is FAR mode.
SystemRun runSystem(const sim::World& world, const Task& task, bool interaction_enabled,
                    const SystemRunSettings& settings);

}  // namespace ifar::scenarios
