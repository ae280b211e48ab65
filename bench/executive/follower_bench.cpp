// Speed of one follower cycle (runs at 50 Hz on the vehicle) and of one executive step, with a
// cluttered local obstacle set.

#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "executive/doorway/doorway.hpp"
#include "executive/follower/follower.hpp"
#include "executive/modes/executive.hpp"

namespace {

using ifar::geometry::Point;

/// `count` points on the outlines of random boxes within 8 m of the origin, leaving the start clear.
std::vector<Point> clutter(int count)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(-8.0, 8.0);
  std::uniform_real_distribution<double> along(-0.5, 0.5);
  std::vector<Point> points;
  while (static_cast<int>(points.size()) < count) {
    const Point centre(position(random), position(random));
    if (centre.norm() < 2.0) {
      continue;
    }
    for (int index = 0; index < 40; ++index) {
      const double offset = along(random);
      points.emplace_back(centre + (index % 2 == 0 ? Point(offset, 0.5) : Point(0.5, offset)));
    }
  }
  return points;
}

void BM_FollowerCycle(benchmark::State& state)
{
  const std::vector<Point> points = clutter(static_cast<int>(state.range(0)));
  const ifar::common::VehicleSettings vehicle;
  const ifar::executive::DifferentialDrive drive(vehicle);
  const ifar::executive::FollowerSettings settings;
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(
        ifar::executive::follow({0.0, 0.0, 0.3}, {6.0, 5.0}, true, points, settings, drive));
  }
  state.counters["points"] = static_cast<double>(points.size());
}
BENCHMARK(BM_FollowerCycle)->Arg(500)->Arg(5000)->Unit(benchmark::kMicrosecond);

void BM_ExecutiveStepFollowing(benchmark::State& state)
{
  const ifar::common::VehicleSettings vehicle;
  ifar::executive::Executive executive(ifar::executive::ExecutiveSettings{}, vehicle);
  ifar::executive::Inputs inputs;
  ifar::executive::Path path;
  path.goal_id = 1;
  path.sequence = 1;
  path.valid = true;
  path.waypoints.resize(2);
  path.waypoints[1].position = Point(6.0, 5.0);
  std::int64_t now_us = 1'000'000;
  inputs.pose = ifar::executive::Stamped<ifar::geometry::Pose2>{{0.0, 0.0, 0.3}, now_us};
  inputs.path = ifar::executive::Stamped<ifar::executive::Path>{path, now_us};
  inputs.force = ifar::executive::Stamped<ifar::executive::ForceReading>{{0.0, false}, now_us};
  inputs.motor = ifar::executive::Stamped<ifar::executive::MotorReading>{{true, false, ""}, now_us};
  inputs.obstacles = ifar::executive::Stamped<std::vector<Point>>{clutter(2000), now_us};
  for ([[maybe_unused]] auto _ : state) {
    now_us += 20'000;
    inputs.pose->utime = inputs.path->utime = inputs.force->utime = inputs.motor->utime =
        inputs.obstacles->utime = now_us;
    benchmark::DoNotOptimize(executive.step(now_us, inputs));
  }
}
BENCHMARK(BM_ExecutiveStepFollowing)->Unit(benchmark::kMicrosecond);

/// A 1.0 m door at the origin in a 0.2 m wall along x (lidar-like points 5 cm apart on both faces), plus
/// `clutter_points` of clutter around it (none within 2 m of the door).
std::vector<Point> doorAndClutter(int clutter_points)
{
  std::vector<Point> points = clutter(clutter_points);
  for (int step = -80; step <= 80; ++step) {
    const double x = 0.05 * step;
    if (std::abs(x) >= 0.5) {
      points.emplace_back(x, -0.1);
      points.emplace_back(x, 0.1);
    }
  }
  return points;
}

/// The executive looks for a doorway on the path ahead every following cycle; this is its cost when
/// there is one (gap search plus the run fit; the fit is skipped when there is none).
void BM_FindDoorway(benchmark::State& state)
{
  const std::vector<Point> points = doorAndClutter(static_cast<int>(state.range(0)));
  const std::vector<Point> path{{-2.0, -2.0}, {-0.15, -0.3}, {1.5, 2.5}};
  const ifar::executive::Footprint footprint;
  const ifar::executive::DoorwaySettings settings;
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(ifar::executive::findDoorway(path, points, footprint, settings));
  }
  state.counters["points"] = static_cast<double>(points.size());
}
BENCHMARK(BM_FindDoorway)->Arg(500)->Arg(5000)->Unit(benchmark::kMicrosecond);

}  // namespace
