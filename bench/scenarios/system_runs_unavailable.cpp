// Built when system/ (target ifar_runner) does not exist: every system run is reported, not faked.
#include "bench/scenarios/system_runs.hpp"

namespace ifar::scenarios {

bool systemRunnerAvailable()
{
  return false;
}

std::vector<std::string> sensingProfileNames()
{
  return {"ideal", "field"};  // named for the rows; nothing is driven under them
}

struct SystemRunner::Settings {};

SystemRunner::SystemRunner(const std::string& /*config_dir*/,
                           const std::vector<std::string>& /*sensing_profiles*/)
{
}

SystemRunner::~SystemRunner() = default;

std::uint64_t SystemRunner::configuredSensingSeed() const
{
  return 1;
}

bool SystemRunner::drawsFromSeed(const std::string& /*sensing*/) const
{
  return false;
}

SystemRun SystemRunner::run(const sim::World& /*world*/, const Task& /*task*/, bool /*interaction_enabled*/,
                            const std::string& /*sensing*/, std::optional<std::uint64_t> /*sensing_seed*/,
                            double /*max_sim_time_s*/) const
{
  SystemRun run;
  run.reason = "runner unavailable: this build has no system/ (target ifar_runner)";
  return run;
}

}  // namespace ifar::scenarios
