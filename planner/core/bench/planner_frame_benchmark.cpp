// One planner update (perception, local graph, merge, search) on simulated VLP-16 revolutions of a room
// with a box, the vehicle driving a curve; and a replan (search only) on the resulting graph.

#include <vector>

#include <benchmark/benchmark.h>

#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "tests/unit/planner_core/simulated_feed.hpp"

namespace ifar::planner {
namespace {

const std::vector<FrameInput>& frames()
{
  static const std::vector<FrameInput> recorded = [] {
    FrameAssembler assembler{InputSettings{}};
    return testing::feedAll(testing::recordSimulation(sim::builtinPushRoom(200.0), 1.0, 0.4, 0.25),
                            assembler);
  }();
  return recorded;
}

void BM_PlannerFrame(benchmark::State& state)
{
  Planner planner{PlannerSettings{}};
  planner.setGoal(Goal{1, geometry::Point(9.0, 8.0)});
  std::size_t index = 0;
  for (auto _ : state) {
    const FrameResult result = planner.processFrame(frames()[index]);
    benchmark::DoNotOptimize(result.path.length_m);
    index = (index + 1) % frames().size();
  }
  state.counters["vertices"] = static_cast<double>(planner.graph().vertexCount());
}
BENCHMARK(BM_PlannerFrame)->Unit(benchmark::kMillisecond);

void BM_PlannerReplan(benchmark::State& state)
{
  Planner planner{PlannerSettings{}};
  for (const FrameInput& frame : frames()) {
    planner.processFrame(frame);
  }
  planner.setGoal(Goal{1, geometry::Point(9.0, 8.0)});
  for (auto _ : state) {
    const FrameResult result = planner.replan();
    benchmark::DoNotOptimize(result.path.length_m);
  }
}
BENCHMARK(BM_PlannerReplan)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ifar::planner
