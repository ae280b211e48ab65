// Graph benchmarks: the AcrosstheCape prior map (build, queries, memory), global search on a tunnel-size
// and a room-size graph, and search time against graph size. How to run it: docs/benchmarks.md ("Micro
// benchmarks").

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/graph/synthetic_worlds.hpp"
#include "common/grid_map/readers.hpp"
#include "common/percentile.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace ifar::graph::bench {
namespace {

using geometry::Point;

const std::string kCapeMap = std::string(IFAR_SHARED_DATA) + "/gppc/AcrosstheCape.map";

double peakMemoryMegabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// CPU time of this thread in microseconds: the machine is shared, so wall-clock percentiles would
/// mostly measure other people's processes.
double threadMicroseconds()
{
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e6 + static_cast<double>(now.tv_nsec) * 1e-3;
}

void AcrossTheCapeBuild(benchmark::State& state)
{
  const auto map = grid_map::readMovingAiMap(kCapeMap);
  if (!map.ok()) {
    state.SkipWithError(("shared data absent: " + map.error).c_str());
    return;
  }
  std::size_t vertices = 0;
  std::size_t edges = 0;
  for ([[maybe_unused]] auto _ : state) {
    const PriorMap prior = buildPriorMap(map.map, 0.0);
    vertices = prior.graph.vertexCount();
    edges = prior.graph.visibilityEdgeCount();
    benchmark::DoNotOptimize(vertices);
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["edges"] = static_cast<double>(edges);
  state.counters["peak_rss_MB"] = peakMemoryMegabytes();
}
BENCHMARK(AcrossTheCapeBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

void AcrossTheCapeQueries(benchmark::State& state)
{
  const auto map = grid_map::readMovingAiMap(kCapeMap);
  const auto scenarios = grid_map::readMovingAiScenarios(kCapeMap + ".scen");
  if (!map.ok() || !scenarios.ok() || scenarios.scenarios.empty()) {
    state.SkipWithError("shared data absent: AcrosstheCape.map / .scen");
    return;
  }
  const PriorMap prior = buildPriorMap(map.map, 0.0);
  const SearchGraph graph = SearchGraph::fromDvGraph(prior.graph);
  SearchScratch scratch;
  std::vector<double> microseconds;
  std::size_t index = 0;
  for ([[maybe_unused]] auto _ : state) {
    const auto& scenario = scenarios.scenarios[index++ % scenarios.scenarios.size()];
    const double begin = threadMicroseconds();
    const auto result = findPath(graph, prior.obstacles, scenario.start, scenario.goal, scratch);
    microseconds.push_back(threadMicroseconds() - begin);
    benchmark::DoNotOptimize(result.length);
  }
  state.counters["cpu_median_us"] = ifar::common::nearestRankPercentile(microseconds, 50.0);
  state.counters["cpu_p99_us"] = ifar::common::nearestRankPercentile(microseconds, 99.0);
  state.counters["peak_rss_MB"] = peakMemoryMegabytes();
}
BENCHMARK(AcrossTheCapeQueries)->Unit(benchmark::kMicrosecond)->Iterations(603);

/// A synthetic field with its graph, the search snapshot and one long query.
struct Scene {
  std::unique_ptr<ObstacleSet> obstacles;
  SearchGraph graph;
  std::size_t vertices = 0;
  Point start;
  Point goal;
};

/// The graph of `field` with one query from `start` to `goal`.
Scene fieldScene(const RectangleField& field, const Point& start, const Point& goal)
{
  Scene scene;
  scene.obstacles = std::make_unique<ObstacleSet>(rectangles(field));
  const DvGraph graph = fullGraph(*scene.obstacles);
  scene.graph = SearchGraph::fromDvGraph(graph);
  scene.vertices = graph.vertexCount();
  scene.start = start;
  scene.goal = goal;
  return scene;
}

Scene tunnelScene()
{
  // 330 m x 270 m (the paper's Tunnel), 400 rectangles = 1,600 corners, corner-to-corner query (~450 m).
  return fieldScene(RectangleField{330.0, 270.0, 20, 20, 3.0, 12.0, 7}, Point(1.0, 1.0), Point(329.0, 269.0));
}

Scene roomScene()
{
  // A 32 m x 32 m room with 16 pieces of furniture.
  return fieldScene(RectangleField{32.0, 32.0, 4, 4, 1.0, 4.0, 11}, Point(0.5, 0.5), Point(31.5, 31.5));
}

void runScene(benchmark::State& state, const Scene& scene)
{
  SearchScratch scratch;
  SearchResult result;
  std::vector<double> microseconds;
  for ([[maybe_unused]] auto _ : state) {
    const double begin = threadMicroseconds();
    result = findPath(scene.graph, *scene.obstacles, scene.start, scene.goal, scratch);
    microseconds.push_back(threadMicroseconds() - begin);
    benchmark::DoNotOptimize(result.length);
  }
  if (result.status != SearchStatus::Found) {
    state.SkipWithError("no path in the synthetic scene");
    return;
  }
  state.counters["vertices"] = static_cast<double>(scene.vertices);
  state.counters["path_m"] = result.length;
  state.counters["expansions"] = static_cast<double>(result.expansions);
  state.counters["cpu_median_us"] = ifar::common::nearestRankPercentile(microseconds, 50.0);
  state.counters["cpu_p99_us"] = ifar::common::nearestRankPercentile(microseconds, 99.0);
}

void TunnelSearch(benchmark::State& state)
{
  static const Scene scene = tunnelScene();
  runScene(state, scene);
}
BENCHMARK(TunnelSearch)->Unit(benchmark::kMicrosecond);

void RoomSearch(benchmark::State& state)
{
  static const Scene scene = roomScene();
  runScene(state, scene);
}
BENCHMARK(RoomSearch)->Unit(benchmark::kMicrosecond);

/// Search time against graph size: a field of 5 m sub-cells with one rectangle (4 corners) each, sized
/// for the requested vertex count, queried corner to corner. Up to 2,000 vertices the graph is built in
/// one go; larger ones are accumulated by merging 40 m local layers as the online planner does.
void SearchSweep(benchmark::State& state)
{
  const int rectangles_wanted = std::max(1, static_cast<int>(state.range(0)) / 4);
  const int columns =
      std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(rectangles_wanted)))));
  const int rows =
      std::max(1, static_cast<int>(std::lround(static_cast<double>(rectangles_wanted) / columns)));
  const RectangleField field{5.0 * columns, 5.0 * rows, columns, rows, 1.0, 4.0, 3};
  const auto loops = rectangles(field);
  Scene scene;
  const DvGraph graph = state.range(0) <= 2000 ? fullGraph(ObstacleSet(loops))
                                               : mergedGraph(loops, field.width_m, field.height_m, 40.0);
  scene.obstacles = std::make_unique<ObstacleSet>(loops);
  scene.graph = SearchGraph::fromDvGraph(graph);
  scene.vertices = graph.vertexCount();
  scene.start = Point(0.2, 0.2);
  scene.goal = Point(field.width_m - 0.2, field.height_m - 0.2);
  runScene(state, scene);
  state.counters["edges"] = static_cast<double>(graph.visibilityEdgeCount());
}
BENCHMARK(SearchSweep)
    ->Unit(benchmark::kMicrosecond)
    ->Arg(100)
    ->Arg(200)
    ->Arg(500)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(5000)
    ->Arg(10000)
    ->Arg(20000);

}  // namespace
}  // namespace ifar::graph::bench
