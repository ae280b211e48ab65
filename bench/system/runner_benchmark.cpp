// How fast the headless runner goes: simulated seconds per wall second for the first 10 simulated seconds
// of the room and the demo room on the shipped config (lidar, planner frames, 50 Hz executive).

#include <benchmark/benchmark.h>

#include <string>

#include "sim/world/world_file.hpp"
#include "system/run_config.hpp"
#include "system/scenario_runner.hpp"

namespace {

constexpr double kSimulatedSeconds = 10.0;

void runWorld(benchmark::State& state, const std::string& world_file)
{
  const std::string source = IFAR_SOURCE_DIR;
  ifar::runner::RunRequest request = ifar::runner::loadRunSettings(source + "/config");
  const ifar::sim::WorldResult loaded = ifar::sim::loadWorldFile(source + "/config/worlds/" + world_file);
  if (!loaded.ok()) {
    state.SkipWithError(loaded.error().c_str());
    return;
  }
  request.world = loaded.world();
  request.goal = request.world.goals.front().position;
  request.max_sim_time_s = kSimulatedSeconds;
  double simulated = 0.0;
  for ([[maybe_unused]] auto _ : state) {
    const ifar::runner::RunSummary summary = ifar::runner::runScenario(request, {});
    benchmark::DoNotOptimize(summary.distance_m);
    simulated += summary.sim_time_s;
  }
  state.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}

void BM_RunnerRoom10s(benchmark::State& state)
{
  runWorld(state, "room.yaml");
}
BENCHMARK(BM_RunnerRoom10s)->Unit(benchmark::kSecond)->UseRealTime();

void BM_RunnerDemoRoom10s(benchmark::State& state)
{
  runWorld(state, "demo_room.yaml");
}
BENCHMARK(BM_RunnerDemoRoom10s)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
