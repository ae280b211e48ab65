#include "sim/simulator/simulator.hpp"

#include <gtest/gtest.h>

#include "sim/generators/generators.hpp"
#include "sim/simulator/builtin_worlds.hpp"

namespace ifar::sim {
namespace {

struct Trajectory {
  std::vector<physics::BodyState> estimates;
  std::vector<physics::BodyState> truths;
  std::vector<physics::BodyState> boxes;
  std::vector<double> forces;
  std::vector<lidar::Vlp16Packet> packets;
};

Trajectory run(std::uint64_t seed)
{
  SimulatorSettings settings;
  settings.seed = seed;
  settings.sensing.pose.jitter_position_m = 0.02;
  settings.sensing.pose.jitter_heading_rad = 0.01;
  Simulator simulator(builtinPushRoom(20.0), common::VehicleSettings{}, settings);
  Trajectory trajectory;
  for (int step = 0; step < 300; ++step) {
    // Push the box, then turn while pushing: contacts, friction and slip all take part.
    simulator.setVelocityCommand(0.6, step < 150 ? 0.0 : 0.4);
    const StepOutput output = simulator.step(0.01);
    trajectory.estimates.push_back(output.pose_estimate);
    trajectory.truths.push_back(output.vehicle);
    trajectory.boxes.push_back(output.objects.at(0));
    trajectory.forces.push_back(output.bumper_force_n);
    trajectory.packets.insert(trajectory.packets.end(), output.packets.begin(), output.packets.end());
  }
  return trajectory;
}

void expectSame(const physics::BodyState& first, const physics::BodyState& second)
{
  EXPECT_EQ(first.pose.x, second.pose.x);
  EXPECT_EQ(first.pose.y, second.pose.y);
  EXPECT_EQ(first.pose.heading, second.pose.heading);
  EXPECT_EQ(first.linear_velocity, second.linear_velocity);
  EXPECT_EQ(first.angular_velocity, second.angular_velocity);
}

TEST(Simulator, SameSeedAndCommandsGiveIdenticalRuns)
{
  const Trajectory first = run(11);
  const Trajectory second = run(11);
  ASSERT_EQ(first.truths.size(), second.truths.size());
  for (std::size_t index = 0; index < first.truths.size(); ++index) {
    expectSame(first.truths[index], second.truths[index]);
    expectSame(first.estimates[index], second.estimates[index]);
    expectSame(first.boxes[index], second.boxes[index]);
    EXPECT_EQ(first.forces[index], second.forces[index]);
  }
  ASSERT_EQ(first.packets.size(), second.packets.size());
  EXPECT_TRUE(first.packets == second.packets);
  // The run did something: the box was pushed and the vehicle turned.
  EXPECT_GT(first.boxes.back().pose.x - first.boxes.front().pose.x, 0.3);
  EXPECT_GT(first.truths.back().pose.heading, 0.3);
}

TEST(Simulator, PoseNoiseFollowsTheSeed)
{
  const Trajectory first = run(11);
  const Trajectory other = run(12);
  EXPECT_EQ(first.truths.back().pose.x, other.truths.back().pose.x);
  EXPECT_NE(first.estimates.back().pose.x, other.estimates.back().pose.x);
  EXPECT_NEAR(first.estimates.back().pose.x, first.truths.back().pose.x, 0.1);
}

TEST(Simulator, CarriesPartialStepsAndEmitsPacketsAtTheSensorRate)
{
  Simulator simulator(builtinRoom(), common::VehicleSettings{}, SimulatorSettings{});
  std::size_t packets = 0;
  const StepOutput half = simulator.step(0.0025);
  EXPECT_EQ(half.time_ns, 0);
  packets += half.packets.size();
  const StepOutput whole = simulator.step(0.0025);
  EXPECT_EQ(whole.time_ns, 5'000'000);
  packets += whole.packets.size();
  for (int step = 0; step < 199; ++step) {
    packets += simulator.step(0.005).packets.size();
  }
  EXPECT_EQ(simulator.timeNanoseconds(), 1'000'000'000);
  // 1 s / 55.296 us = 18085 firings (counting t = 0) = 753 whole packets (754 per second on average).
  EXPECT_EQ(packets, 753u);
}

TEST(Simulator, ReportsTheBumperForceAndGroundTruth)
{
  Simulator simulator(builtinPushRoom(200.0), common::VehicleSettings{}, SimulatorSettings{});
  simulator.setVelocityCommand(0.5, 0.0);
  StepOutput output;
  for (int step = 0; step < 50; ++step) {
    output = simulator.step(0.1);
  }
  EXPECT_NEAR(output.bumper_force_n, common::VehicleSettings{}.maxPushForce(), 15.0);
  ASSERT_EQ(output.objects.size(), 1u);
  EXPECT_EQ(output.objects[0].id, 1);
  EXPECT_EQ(output.utime, SimulatorSettings{}.epoch_utime + 5'000'000);
}

TEST(Simulator, RunsEveryGeneratedWorld)
{
  for (const auto kind :
       {WorldKind::Room, WorldKind::RoomObjects, WorldKind::Office, WorldKind::Tunnel, WorldKind::DemoRoom}) {
    const auto generated = generateWorld(kind, 1);
    ASSERT_TRUE(generated.ok()) << generated.error();
    Simulator simulator(generated.world(), common::VehicleSettings{}, SimulatorSettings{});
    std::size_t packets = 0;
    StepOutput output;
    for (int step = 0; step < 10; ++step) {
      output = simulator.step(0.01);
      packets += output.packets.size();
    }
    EXPECT_EQ(packets, 75u) << worldKindName(kind);
    // Standing still at the start: nothing overlaps the vehicle, nothing drifts.
    EXPECT_NEAR(output.vehicle.pose.x, generated.world().start.x, 1e-4) << worldKindName(kind);
    EXPECT_NEAR(output.vehicle.pose.y, generated.world().start.y, 1e-4) << worldKindName(kind);
    for (std::size_t index = 0; index < output.objects.size(); ++index) {
      EXPECT_NEAR(output.objects[index].pose.x, generated.world().objects[index].pose.x, 1e-3)
          << worldKindName(kind) << " object " << output.objects[index].id;
    }
  }
}

}  // namespace
}  // namespace ifar::sim
