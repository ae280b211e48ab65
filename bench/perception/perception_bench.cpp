// One full VLP-16 revolution (16 x 1800 returns) of a walled room with boxes through the whole
// perception pipeline, and each stage on its own. Target: <= 20 ms per frame on one core.

#include <algorithm>
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "planner/perception/background_memory.hpp"
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

/// The same revolution with each return at its own firing time, as a VLP-16 gives them: its 16 lasers
/// fire 2.304 us apart (the datasheet's firing sequence), so no two returns of a firing share a time.
void BM_MotionCompensationPerLaserTimes(benchmark::State& state)
{
  const RoomFrame& frame = roomFrame();
  std::vector<SensorPoint> points = frame.points;
  constexpr double kLaserSpacingS = 2.304e-6;
  for (std::size_t index = 0; index < points.size(); ++index) {
    points[index].time_offset_s += static_cast<double>(index % 16) * kLaserSpacingS;
  }
  const ifar::common::Span<const SensorPoint> span(points.data(), points.size());
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(compensateMotion(span, frame.input.mount, frame.input.motion));
  }
}
BENCHMARK(BM_MotionCompensationPerLaserTimes)->Unit(benchmark::kMillisecond);

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

/// The layer after a long drive: remembered walls of a network of 4 m wide corridors every 20 m over the
/// whole layer (two cells thick, as a drifting pose draws them), one scan's boxes near the vehicle.
ClassifiedPoints mapScalePoints(const PerceptionSettings& settings)
{
  ClassifiedPoints points;
  const double half = 0.5 * settings.layer_size_m - 1.0;
  const double step = settings.cell_size_m;
  for (double line = -half + 10.0; line < half; line += 20.0) {
    for (const double wall : {line - 2.0, line - 2.0 + step, line + 2.0, line + 2.0 + step}) {
      for (double along = -half; along < half; along += step) {
        const bool in_crossing = std::fmod(along + half + 10.0, 20.0) < 4.0;  // the side corridor's mouth
        if (!in_crossing) {
          points.background.emplace_back(wall, along);
          points.background.emplace_back(along, wall);
        }
      }
    }
  }
  for (double x = 1.5; x < 2.5; x += step) {
    for (double y = -0.5; y < 0.5; y += step) {
      points.movable.emplace_back(x, y);
    }
  }
  return points;
}

void BM_LocalLayerAtMapScale(benchmark::State& state)
{
  const PerceptionSettings settings;
  const ClassifiedPoints points = mapScalePoints(settings);
  std::size_t polygons = 0;
  for ([[maybe_unused]] auto _ : state) {
    const LocalLayer layer = buildLocalLayer(points, ifar::geometry::Point(0.0, 0.0), settings);
    polygons = layer.polygons.size();
    benchmark::DoNotOptimize(polygons);
  }
  state.counters["points"] = static_cast<double>(points.background.size() + points.movable.size());
  state.counters["polygons"] = static_cast<double>(polygons);
}
BENCHMARK(BM_LocalLayerAtMapScale)->Unit(benchmark::kMillisecond);

/// The remembered background the planner draws into each frame's layer after a long drive: every cell of
/// the corridor network inside the layer's square.
void BM_RememberedCellsAtMapScale(benchmark::State& state)
{
  const PerceptionSettings settings;
  const ClassifiedPoints points = mapScalePoints(settings);
  BackgroundMemory memory(settings.cell_size_m, settings.background_votes);
  memory.remember(
      ifar::common::Span<const ifar::geometry::Point>(points.background.data(), points.background.size()));
  const ifar::geometry::Point half = ifar::geometry::Point::Constant(0.5 * settings.layer_size_m);
  std::size_t cells = 0;
  for ([[maybe_unused]] auto _ : state) {
    cells = memory.cellsWithin(-half, half).size();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(BM_RememberedCellsAtMapScale)->Unit(benchmark::kMillisecond);

}  // namespace
