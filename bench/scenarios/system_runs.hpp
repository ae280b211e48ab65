#pragma once
// Tables II and III (system level): the headless runner (system/) drives the vehicle
// through a task with FAR mode or ours. CMake builds this against the runner when the ifar_runner target
// exists (system_runs_runner.cpp) and otherwise against a stand-in that reports "runner unavailable"
// (system_runs_unavailable.cpp), so Tables II and III always come out of the same command.

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bench/scenarios/task_selection.hpp"
#include "common/geometry/pose2.hpp"
#include "sim/world/world.hpp"
#include "system/loss_accounting.hpp"

namespace ifar::scenarios {

struct SystemRun {
  bool ran = false;  // false: the runner is not available (or refused the request); see `reason`
  bool arrived = false;
  /// Empty when the run ended on its own (arrived or not); "error" when the runner threw or crashed,
  /// "timeout" when it hung and was killed. `reason` says how.
  std::string failure_status;
  std::string reason;
  double distance_m = 0.0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  int pushes = 0;
  // The runner's planner frames, wall ms (runner::RunSummary::planner_frame and ::interaction).
  double frame_median_ms = NAN;
  double frame_p99_ms = NAN;
  double frame_max_ms = NAN;
  double interaction_max_ms = NAN;
  int undecided_saturated_pushes = 0;  // runner::RunSummary::undecided_saturated_pushes
  int escalations = 0;                 // runner::RunSummary::escalations
  // runner::RunSummary::losses: the distance beyond the achievable way and its buckets (NaN when not
  // accounted).
  double excess_m = NAN;
  runner::LossBuckets losses = runner::notAccounted();
  std::vector<geometry::Pose2> trajectory;
};

/// Every field of the run as a child process's answer (answer_text.hpp), and back: exact, NaN included.
/// nullopt when `answer` is not such an answer.
std::string toAnswer(const SystemRun& run);
std::optional<SystemRun> systemRunFromAnswer(std::string_view answer);

/// False when this build has no headless runner.
bool systemRunnerAvailable();

/// The simulator's sensing profiles a run can be driven under ("ideal" first).
std::vector<std::string> sensingProfileNames();

/// The headless runner with the settings every run of a suite shares, read once: a suite that runs for
/// an hour must not pick up a config file edited half-way through (nor fail on it run by run).
class SystemRunner {
 public:
  /// Reads vehicle.yaml, sim.yaml, planner.yaml and executive.yaml from `config_dir`, once under each of
  /// `sensing_profiles` (sensingProfileNames()). Throws std::runtime_error naming the file and key when one
  /// is bad (not when the build has no runner).
  SystemRunner(const std::string& config_dir, const std::vector<std::string>& sensing_profiles);
  ~SystemRunner();
  SystemRunner(const SystemRunner&) = delete;
  SystemRunner& operator=(const SystemRunner&) = delete;

  /// Drives from task.start to task.goal in `world` (its start and goals replaced by the task's) for at
  /// most `max_sim_time_s` simulated seconds under the sensing profile `sensing` (one of the
  /// constructor's), its sensor models drawing from `sensing_seed` (nullopt: sim.yaml's seed).
  /// `interaction_enabled` false is FAR mode. Safe to call from several threads at once.
  SystemRun run(const sim::World& world, const Task& task, bool interaction_enabled,
                const std::string& sensing, std::optional<std::uint64_t> sensing_seed,
                double max_sim_time_s) const;

  /// The seed sim.yaml gives the sensor models.
  std::uint64_t configuredSensingSeed() const;
  /// False when the profile's sensor models draw nothing from the seed (every seed drives the same run),
  /// or when `sensing` is not one of the constructor's.
  bool drawsFromSeed(const std::string& sensing) const;

 private:
  struct Settings;
  std::unique_ptr<const Settings> settings_;
};

}  // namespace ifar::scenarios
