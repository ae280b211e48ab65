// Cost of the executive's own lidar decoding (executive/obstacles): one VLP-16 packet into the local
// obstacle points (754 per second on the vehicle), the per-cycle points() query (50 Hz) and the
// follower on those points, with packets the simulator makes in its push room.

#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "executive/follower/follower.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/obstacles/local_obstacles.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"

namespace {

using ifar::executive::LocalObstacles;
using ifar::executive::ObstacleSettings;

constexpr std::int64_t kPacketPeriodUs = 1327;  // 754 packets per second
constexpr std::int64_t kStartUs = 1'700'000'000'000'000;

struct Recording {
  std::vector<std::vector<std::uint8_t>> packets;
  ifar::geometry::Pose2 pose;
};

/// 0.3 s of packets (three revolutions) from the vehicle standing at the start of the push room.
const Recording& recording()
{
  static const Recording result = [] {
    Recording made;
    ifar::sim::Simulator simulator(ifar::sim::builtinPushRoom(40.0), ifar::common::VehicleSettings{},
                                   ifar::sim::SimulatorSettings{});
    for (int step = 0; step < 30; ++step) {
      const ifar::sim::StepOutput output = simulator.step(0.01);
      made.pose = output.pose_estimate.pose;
      for (const auto& packet : output.packets) {
        made.packets.emplace_back(packet.begin(), packet.end());
      }
    }
    return made;
  }();
  return result;
}

/// Feeds every recorded packet once, 1327 us apart; returns the time of the last.
std::int64_t feed(LocalObstacles& obstacles, const Recording& packets)
{
  std::int64_t utime = kStartUs;
  for (const auto& packet : packets.packets) {
    utime += kPacketPeriodUs;
    obstacles.addPacket(ifar::common::ByteView(packet.data(), packet.size()), utime);
  }
  return utime;
}

void BM_AddPacket(benchmark::State& state)
{
  const Recording& packets = recording();
  const ifar::common::VehicleSettings vehicle;
  LocalObstacles obstacles(ObstacleSettings{}, vehicle);
  obstacles.addPose(kStartUs, packets.pose);
  std::int64_t utime = kStartUs;
  std::size_t index = 0;
  for ([[maybe_unused]] auto _ : state) {
    const auto& packet = packets.packets[index];
    utime += kPacketPeriodUs;
    benchmark::DoNotOptimize(
        obstacles.addPacket(ifar::common::ByteView(packet.data(), packet.size()), utime));
    index = (index + 1) % packets.packets.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AddPacket)->Unit(benchmark::kMicrosecond);

/// points() as the daemon calls it every cycle; counters: returns kept per revolution (0.1 s, every
/// return) and points handed to the follower (keep_s, one per cell).
void BM_PointsPerCycle(benchmark::State& state)
{
  const Recording& packets = recording();
  const ifar::common::VehicleSettings vehicle;
  ObstacleSettings settings;
  settings.cell_m = static_cast<double>(state.range(0)) / 100.0;
  LocalObstacles obstacles(settings, vehicle);
  obstacles.addPose(kStartUs, packets.pose);
  const std::int64_t now = feed(obstacles, packets);
  ObstacleSettings one_sweep = settings;
  one_sweep.cell_m = 0.0;
  one_sweep.keep_s = 0.1;
  LocalObstacles sweep(one_sweep, vehicle);
  sweep.addPose(kStartUs, packets.pose);
  const std::int64_t sweep_now = feed(sweep, packets);
  std::size_t count = 0;
  for ([[maybe_unused]] auto _ : state) {
    const std::vector<ifar::geometry::Point> points = obstacles.points(now);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["points_per_sweep"] = static_cast<double>(sweep.points(sweep_now).size());
  state.counters["points_to_follower"] = static_cast<double>(count);
}
BENCHMARK(BM_PointsPerCycle)->Arg(0)->Arg(5)->Unit(benchmark::kMicrosecond);

/// One follower cycle on those points (cell size in cm as the argument).
void BM_FollowerOnLidarPoints(benchmark::State& state)
{
  const Recording& packets = recording();
  const ifar::common::VehicleSettings vehicle;
  ObstacleSettings settings;
  settings.cell_m = static_cast<double>(state.range(0)) / 100.0;
  LocalObstacles obstacles(settings, vehicle);
  obstacles.addPose(kStartUs, packets.pose);
  const std::vector<ifar::geometry::Point> points = obstacles.points(feed(obstacles, packets));
  ifar::executive::FollowerSettings follower;
  follower.footprint = ifar::executive::vehicleFootprint(vehicle, 0.45);
  const ifar::executive::DifferentialDrive drive(vehicle);
  const ifar::geometry::Point target = packets.pose.transform(ifar::geometry::Point(8.0, 3.0));
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(ifar::executive::follow(
        packets.pose, target, true,
        ifar::common::Span<const ifar::geometry::Point>(points.data(), points.size()), follower, drive));
  }
  state.counters["points"] = static_cast<double>(points.size());
}
BENCHMARK(BM_FollowerOnLidarPoints)->Arg(0)->Arg(5)->Unit(benchmark::kMicrosecond);

}  // namespace
