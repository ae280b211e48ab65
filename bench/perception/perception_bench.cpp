// One full VLP-16 revolution (16 x 1800 returns) of a walled room with boxes through the whole
// perception pipeline, and each stage on its own. Target: <= 20 ms per frame on one core.

#include <algorithm>
#include <vector>

#include <benchmark/benchmark.h>

#include "planner/perception/classification.hpp"
#include "planner/perception/height_filter.hpp"
#include "planner/perception/local_layer.hpp"
#include "planner/perception/motion_compensation.hpp"
#include "planner/perception/perception_pipeline.hpp"
#include "planner/perception/synthetic/synthetic_scan.hpp"

namespace {

using namespace ifar::perception;  // NOLINT(google-build-using-namespace): benchmark file, not a header

/// A revolution taken while driving 0.1 m forward and turning 3 degrees, as at 1 m/s.
struct RoomFrame {
  std::vector<SensorPoint> points;
  PerceptionInput input;
  PerceptionSettings settings;

  RoomFrame()
  {
    input.mount = SensorMount::Identity();
    input.mount.translation() = Eigen::Vector3d(0.2, 0.0, 0.8);
    input.motion.vehicle_at_start = Eigen::Isometry3d::Identity();
    input.motion.vehicle_at_end = Eigen::Isometry3d::Identity();
    input.motion.vehicle_at_end.translation() = Eigen::Vector3d(0.1, 0.0, 0.0);
    input.motion.vehicle_at_end.linear() =
        Eigen::AngleAxisd(3.0 * 3.14159265358979323846 / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    input.motion.duration_s = 0.1;
    synthetic::RevolutionSettings revolution;
    revolution.ceiling_height_m = 3.0;
    points = synthetic::simulateRevolution(synthetic::roomWithBoxes(), input.mount, revolution);
    input.points = points;
  }
};

const RoomFrame& roomFrame()
{
  static const RoomFrame frame;
  return frame;
}

void BM_PerceptionFullFrame(benchmark::State& state)
{
  const RoomFrame& frame = roomFrame();
  std::size_t polygons = 0;
  for ([[maybe_unused]] auto _ : state) {
    const PerceptionResult result = runPerception(frame.input, frame.settings);
    polygons = result.layer.polygons.size();
    benchmark::DoNotOptimize(polygons);
  }
  state.counters["points"] = static_cast<double>(frame.points.size());
  state.counters["polygons"] = static_cast<double>(polygons);
}
BENCHMARK(BM_PerceptionFullFrame)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("p99", [](const std::vector<double>& values) {
      // With --benchmark_repetitions=N: the repetition at the 99th percentile (the worst below 100).
      std::vector<double> sorted = values;
      std::sort(sorted.begin(), sorted.end());
      return sorted[static_cast<std::size_t>(0.99 * static_cast<double>(sorted.size() - 1))];
    });

void BM_MotionCompensation(benchmark::State& state)
{
  const RoomFrame& frame = roomFrame();
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(compensateMotion(frame.input.points, frame.input.mount, frame.input.motion));
  }
}
BENCHMARK(BM_MotionCompensation)->Unit(benchmark::kMillisecond);

void BM_HeightFilterAndClassification(benchmark::State& state)
{
  const RoomFrame& frame = roomFrame();
  const std::vector<WorldPoint> world =
      compensateMotion(frame.input.points, frame.input.mount, frame.input.motion);
  for ([[maybe_unused]] auto _ : state) {
    const HeightFilterResult filtered = filterObstaclePoints(world, frame.settings);
    benchmark::DoNotOptimize(classifyByReflectivity(filtered.obstacle_points, tagReading(frame.settings)));
  }
}
BENCHMARK(BM_HeightFilterAndClassification)->Unit(benchmark::kMillisecond);

void BM_LocalLayer(benchmark::State& state)
{
  const RoomFrame& frame = roomFrame();
  const std::vector<WorldPoint> world =
      compensateMotion(frame.input.points, frame.input.mount, frame.input.motion);
  const HeightFilterResult filtered = filterObstaclePoints(world, frame.settings);
  const ClassifiedPoints classified =
      classifyByReflectivity(filtered.obstacle_points, tagReading(frame.settings));
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(buildLocalLayer(classified, ifar::geometry::Point(0.1, 0.0), frame.settings));
  }
}
BENCHMARK(BM_LocalLayer)->Unit(benchmark::kMillisecond);

}  // namespace
