// Simulator speed: lidar rays per second on a tunnel-sized world (330 m x 270 m, hundreds of walls) and
// the wall time of a headless room drive of about 9 m with the lidar running.

#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include "sim/generators/generators.hpp"
#include "sim/lidar/lidar_scene.hpp"
#include "sim/lidar/vlp16_scanner.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"

namespace {

using ifar::sim::lidar::LidarScene;
using ifar::sim::lidar::LidarSceneSettings;
using ifar::sim::lidar::Ray;

/// Full VLP-16 revolutions (16 lasers x 1800 azimuths) from random positions in a tunnel-sized world.
void castRevolutions(benchmark::State& state, const ifar::sim::World& world)
{
  const LidarScene scene = LidarScene::fromWorld(world, LidarSceneSettings{});
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> x_position(world.bounds_min.x() + 5.0, world.bounds_max.x() - 5.0);
  std::uniform_real_distribution<double> y_position(world.bounds_min.y() + 5.0, world.bounds_max.y() - 5.0);
  std::array<double, 16> slopes{};
  std::array<double, 16> cosines{};
  for (std::size_t laser = 0; laser < 16; ++laser) {
    const double elevation = ifar::sim::lidar::kVlp16VerticalAnglesDeg[laser] * M_PI / 180.0;
    slopes[laser] = std::tan(elevation);
    cosines[laser] = std::cos(elevation);
  }
  std::int64_t rays = 0;
  double checksum = 0.0;
  for ([[maybe_unused]] auto _ : state) {
    const double origin_x = x_position(random);
    const double origin_y = y_position(random);
    for (int azimuth = 0; azimuth < 1800; ++azimuth) {
      const double direction = azimuth * 0.2 * M_PI / 180.0;
      Ray ray;
      ray.origin_x = origin_x;
      ray.origin_y = origin_y;
      ray.height = 0.8;
      ray.direction_x = std::cos(direction);
      ray.direction_y = std::sin(direction);
      for (std::size_t laser = 0; laser < 16; ++laser) {
        ray.slope = slopes[laser];
        ray.max_horizontal = 100.0 * cosines[laser];
        checksum += scene.cast(ray).horizontal_distance;
      }
    }
    rays += std::int64_t{1800} * 16;
  }
  benchmark::DoNotOptimize(checksum);
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
  state.counters["obstacles"] = static_cast<double>(world.obstacles.size());
  state.counters["segments"] = static_cast<double>(scene.staticSegmentCount());
}

/// The project's generated Tunnel world (sim/generators, seed 1).
void BM_TunnelRayCasting(benchmark::State& state)
{
  castRevolutions(state, ifar::sim::generateTunnel(1));
}
BENCHMARK(BM_TunnelRayCasting)->Unit(benchmark::kMillisecond);

/// A 330 m x 270 m maze of 15 m corridors with about 320 thin walls (sim/simulator builtin).
void BM_MazeRayCasting(benchmark::State& state)
{
  castRevolutions(state, ifar::sim::builtinTunnelNetwork());
}
BENCHMARK(BM_MazeRayCasting)->Unit(benchmark::kMillisecond);

/// The whole simulator (physics at 200 Hz, VLP-16 packets) stepping in lock-step at 100 Hz while the
/// vehicle drives about 9 m across a 32 m room and pushes a light box on the way.
void BM_HeadlessRoomDrive(benchmark::State& state)
{
  double distance = 0.0;
  std::size_t packets = 0;
  for ([[maybe_unused]] auto _ : state) {
    ifar::sim::Simulator simulator(ifar::sim::builtinPushRoom(20.0, 0.5, 0.6, 4.0, 32.0),
                                   ifar::common::VehicleSettings{}, ifar::sim::SimulatorSettings{});
    const double start_x = simulator.physics().vehicleState().pose.x;
    packets = 0;
    for (int step = 0; step < 1100; ++step) {
      simulator.setVelocityCommand(1.0, 0.0);
      packets += simulator.step(0.01).packets.size();
    }
    distance = simulator.physics().vehicleState().pose.x - start_x;
  }
  state.counters["distance_m"] = distance;
  state.counters["packets"] = static_cast<double>(packets);
}
BENCHMARK(BM_HeadlessRoomDrive)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
