// One planner update (perception, local graph, merge, search) on simulated VLP-16 revolutions of a room
// with a box, the vehicle driving a curve; and a replan (search only) on the resulting graph. The demo
// room variants drive towards the doorway box with interaction planning (cache in use, as deployed), and
// run a fresh planner's first frame (every object planned from scratch). The tunnel also with the pose
// jittered as a state estimator's is.

#include <algorithm>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/world/world_file.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

const std::vector<FrameInput>& frames()
{
  static const std::vector<FrameInput> recorded = [] {
    FrameAssembler assembler{InputSettings{}};
    return test_support::feedAll(test_support::recordSimulation(sim::builtinPushRoom(200.0), 1.0, 0.4, 0.25),
                                 assembler);
  }();
  return recorded;
}

void BM_PlannerFrame(benchmark::State& state)
{
  Planner planner{PlannerSettings{}};
  planner.setGoal(Goal{1, geometry::Point(9.0, 8.0)});
  std::size_t index = 0;
  for ([[maybe_unused]] auto _ : state) {
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
  for ([[maybe_unused]] auto _ : state) {
    const FrameResult result = planner.replan();
    benchmark::DoNotOptimize(result.path.length_m);
  }
}
BENCHMARK(BM_PlannerReplan)->Unit(benchmark::kMicrosecond);

/// Frames of the vehicle driving straight at `linear` m/s for `seconds` from the start of a world file under
/// config/worlds; empty when the file does not load.
std::vector<FrameInput> worldFileFrames(const std::string& file, double seconds, double linear)
{
  const sim::WorldResult world = sim::loadWorldFile(std::string(IFAR_SOURCE_DIR) + "/config/worlds/" + file);
  if (!world.ok()) {
    return {};
  }
  FrameAssembler assembler{InputSettings{}};
  return test_support::feedAll(test_support::recordSimulation(world.world(), seconds, linear), assembler);
}

/// One counter of the frames benchmarks: its name and what it reads off each frame's result.
struct FrameCounter {
  const char* name;
  double (*value)(const FrameResult&);
};

/// Processes `frames` in turn (from the first again after the last), one per iteration, and reports each
/// counter's mean per frame.
void processFramesInTurn(benchmark::State& state, Planner& planner, const std::vector<FrameInput>& frames,
                         std::initializer_list<FrameCounter> counters)
{
  std::vector<double> sums(counters.size(), 0.0);
  std::size_t index = 0;
  for ([[maybe_unused]] auto _ : state) {
    const FrameResult result = planner.processFrame(frames[index]);
    std::size_t counter_index = 0;
    for (const FrameCounter& counter : counters) {
      sums[counter_index++] += counter.value(result);
    }
    benchmark::DoNotOptimize(result.path.length_m);
    index = (index + 1) % frames.size();
  }
  const double iterations = static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
  std::size_t counter_index = 0;
  for (const FrameCounter& counter : counters) {
    state.counters[counter.name] = sums[counter_index++] / iterations;
  }
}

const std::vector<FrameInput>& demoRoomFrames()
{
  static const std::vector<FrameInput> recorded = worldFileFrames("demo_room.yaml", 2.0, 1.0);
  return recorded;
}

void BM_PlannerFrameDemoRoom(benchmark::State& state)
{
  if (demoRoomFrames().empty()) {
    state.SkipWithError("config/worlds/demo_room.yaml did not load");
    return;
  }
  Planner planner{PlannerSettings{}};
  planner.setGoal(Goal{1, geometry::Point(8.0, 26.0)});
  processFramesInTurn(
      state, planner, demoRoomFrames(),
      {{"interaction_ms", [](const FrameResult& result) { return result.status.timings.interaction_ms; }},
       {"pushes", [](const FrameResult& result) { return static_cast<double>(result.path.pushes.size()); }}});
}
BENCHMARK(BM_PlannerFrameDemoRoom)->Unit(benchmark::kMillisecond);

/// The first frame of a fresh planner: every object planned from scratch (no cache), the worst frame.
void BM_PlannerFirstFrameDemoRoom(benchmark::State& state)
{
  if (demoRoomFrames().empty()) {
    state.SkipWithError("config/worlds/demo_room.yaml did not load");
    return;
  }
  double interaction_ms = 0.0;
  for ([[maybe_unused]] auto _ : state) {
    state.PauseTiming();
    Planner planner{PlannerSettings{}};
    planner.setGoal(Goal{1, geometry::Point(8.0, 26.0)});
    state.ResumeTiming();
    const FrameResult result = planner.processFrame(demoRoomFrames().front());
    interaction_ms += result.status.timings.interaction_ms;
    benchmark::DoNotOptimize(result.path.length_m);
  }
  const double iterations = static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.counters["interaction_ms"] = interaction_ms / iterations;
}
BENCHMARK(BM_PlannerFirstFrameDemoRoom)->Unit(benchmark::kMillisecond);

const std::vector<FrameInput>& tunnelFrames()
{
  static const std::vector<FrameInput> recorded = worldFileFrames("tunnel.yaml", 4.0, 1.0);
  return recorded;
}

/// The tunnel's first tunnel, 100 m lidar range, with the local layer's side as the argument (metres):
/// what a layer that holds the whole sensor range costs per frame.
void BM_PlannerFrameTunnel(benchmark::State& state)
{
  if (tunnelFrames().empty()) {
    state.SkipWithError("config/worlds/tunnel.yaml did not load");
    return;
  }
  PlannerSettings settings;
  settings.perception.layer_size_m = static_cast<double>(state.range(0));
  Planner planner{settings};
  planner.setGoal(Goal{1, geometry::Point(211.5, 160.2)});
  processFramesInTurn(
      state, planner, tunnelFrames(),
      {{"perception_ms", [](const FrameResult& result) { return result.status.timings.perception_ms; }},
       {"local_graph_ms", [](const FrameResult& result) { return result.status.timings.local_graph_ms; }}});
  state.counters["vertices"] = static_cast<double>(planner.graph().vertexCount());
}
BENCHMARK(BM_PlannerFrameTunnel)->Arg(60)->Arg(120)->Arg(200)->Unit(benchmark::kMillisecond);

/// `frame` as a state estimator that jitters places it: the poses at the scan's start and end each off by
/// Gaussian noise of `position_m` on x and y and `heading_rad` on the heading (as the simulator's pose
/// noise reaches the planner through the poses interpolated at the scan's ends).
FrameInput jittered(FrameInput frame, double position_m, double heading_rad, std::mt19937& random)
{
  std::normal_distribution<double> position(0.0, position_m);
  std::normal_distribution<double> heading(0.0, heading_rad);
  for (Eigen::Isometry3d* pose : {&frame.motion.vehicle_at_start, &frame.motion.vehicle_at_end}) {
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    offset.linear() = Eigen::AngleAxisd(heading(random), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d turned = pose->translation();
    *pose = offset * *pose;
    pose->translation() = turned + Eigen::Vector3d(position(random), position(random), 0.0);
  }
  return frame;
}

/// The tunnel's first tunnel (200 m layer) with pose jitter: the argument is the position noise in
/// millimetres (the heading's is 0.15 mrad per mm: 2 mm -> 0.3 mrad, 20 mm -> 3 mrad, 50 mm -> 7.5 mrad).
/// The frames are driven again and again with fresh noise, as a vehicle that comes by the same walls.
void BM_PlannerFrameTunnelJitter(benchmark::State& state)
{
  if (tunnelFrames().empty()) {
    state.SkipWithError("config/worlds/tunnel.yaml did not load");
    return;
  }
  const double position_m = static_cast<double>(state.range(0)) / 1000.0;
  const double heading_rad = 0.15 * position_m;
  Planner planner{PlannerSettings{}};
  planner.setGoal(Goal{1, geometry::Point(211.5, 160.2)});
  std::mt19937 random(1);
  std::size_t index = 0;
  StageTimings sums;
  FrameWork work;
  for ([[maybe_unused]] auto _ : state) {
    state.PauseTiming();
    const FrameInput frame = jittered(tunnelFrames()[index], position_m, heading_rad, random);
    state.ResumeTiming();
    const FrameResult result = planner.processFrame(frame);
    benchmark::DoNotOptimize(result.path.length_m);
    sums.perception_ms += result.status.timings.perception_ms;
    sums.local_graph_ms += result.status.timings.local_graph_ms;
    sums.merge_ms += result.status.timings.merge_ms;
    sums.search_ms += result.status.timings.search_ms;
    work = result.status.work;
    index = (index + 1) % tunnelFrames().size();
  }
  const double iterations = static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.counters["perception_ms"] = sums.perception_ms / iterations;
  state.counters["local_graph_ms"] = sums.local_graph_ms / iterations;
  state.counters["merge_ms"] = sums.merge_ms / iterations;
  state.counters["search_ms"] = sums.search_ms / iterations;
  state.counters["vertices"] = static_cast<double>(planner.graph().vertexCount());
  state.counters["polygon_vertices"] = static_cast<double>(work.polygon_vertices);
  state.counters["remembered_cells"] = static_cast<double>(work.remembered_cells);
  state.counters["checked_cells"] = static_cast<double>(work.checked_cells);
}
BENCHMARK(BM_PlannerFrameTunnelJitter)->Arg(0)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ifar::planner
