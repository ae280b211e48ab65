// Built when sim/runner (target ifar_runner) does not exist: every system run is reported, not faked.
#include "bench/scenarios/system_runs.hpp"

namespace ifar::scenarios {

bool systemRunnerAvailable()
{
  return false;
}

SystemRun runSystem(const sim::World& /*world*/, const Task& /*task*/, bool /*interaction_enabled*/,
                    const SystemRunSettings& /*settings*/)
{
  SystemRun run;
  run.reason = "runner unavailable: this build has no sim/runner (target ifar_runner)";
  return run;
}

}  // namespace ifar::scenarios
