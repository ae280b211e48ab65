// Whole runs of the simulator node under the field profile: deterministic to the byte for one seed,
// different from the ideal profile and from another seed, and wheels that slip under a push near the
// traction limit.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "common/vehicle.hpp"
#include "sensing_run.hpp"
#include "sim/simulator/builtin_worlds.hpp"

namespace ifar::sim::testing {
namespace {

SimNodeSettings withProfile(SensingProfile profile, std::uint64_t seed)
{
  SimNodeSettings settings;
  settings.simulator.seed = seed;
  settings.simulator.sensing = sensingProfile(profile);
  return settings;
}

TEST(FieldProfile, SameSeedSameBytes)
{
  const World world = builtinPushRoom(60.0);
  const RunBytes first = runNode(world, withProfile(SensingProfile::kField, 3), 800, 0.5, 0.4);
  const RunBytes second = runNode(world, withProfile(SensingProfile::kField, 3), 800, 0.5, 0.4);
  ASSERT_GT(first.packets.size(), 1'000'000u);
  EXPECT_TRUE(first.packets == second.packets);
  EXPECT_TRUE(first.frames == second.frames);
  EXPECT_TRUE(first.poses == second.poses);
  const RunBytes other_seed = runNode(world, withProfile(SensingProfile::kField, 4), 800, 0.5, 0.4);
  EXPECT_FALSE(first.packets == other_seed.packets);
  EXPECT_FALSE(first.poses == other_seed.poses);
  const RunBytes ideal = runNode(world, withProfile(SensingProfile::kIdeal, 3), 800, 0.5, 0.4);
  EXPECT_FALSE(first.packets == ideal.packets);
  EXPECT_FALSE(first.frames == ideal.frames);
}

TEST(FieldProfile, PosesAreLateAndOff)
{
  const RunBytes run = runNode(builtinPushRoom(60.0), withProfile(SensingProfile::kField, 3), 800, 0.5, 0.4);
  const SensingSettings field = sensingProfile(SensingProfile::kField);
  ASSERT_FALSE(run.pose_messages.empty());
  double largest_error = 0.0;
  for (const auto& pose : run.pose_messages) {
    // Each pose is stamped with the time it is valid at: the latency before the step that sent it.
    const auto sent = std::find_if(run.outputs.begin(), run.outputs.end(), [&](const StepOutput& output) {
      return output.pose_estimate_utime == pose.utime;
    });
    ASSERT_NE(sent, run.outputs.end());
    if (sent->time_ns > 100'000'000) {  // before the latency has passed, the first estimate is repeated
      EXPECT_EQ(sent->utime - pose.utime, std::llround(field.pose.latency_s * 1e6));
      largest_error = std::max(largest_error, std::hypot(pose.position[0] - sent->pose_estimate.pose.x,
                                                         pose.position[1] - sent->pose_estimate.pose.y));
    }
  }
  EXPECT_EQ(largest_error, 0.0);
  // The estimate is not the truth.
  const StepOutput& last = run.outputs.back();
  EXPECT_GT(std::hypot(last.pose_estimate.pose.x - last.vehicle.pose.x,
                       last.pose_estimate.pose.y - last.vehicle.pose.y),
            0.001);
}

/// The body's forward speed and the left drive's reported rim speed, averaged over the last second of a
/// straight push at 0.5 m/s.
struct PushSpeeds {
  double body = 0.0;
  double wheel = 0.0;
  double force = 0.0;
};

PushSpeeds push(const World& world, const SimNodeSettings& settings)
{
  const common::VehicleSettings vehicle;
  const RunBytes run = runNode(world, settings, 1600, 0.5, 0.0);
  PushSpeeds speeds;
  const int count = 200;
  for (std::size_t index = run.outputs.size() - count; index < run.outputs.size(); ++index) {
    speeds.body += run.outputs[index].vehicle.linear_velocity.x() / count;
    speeds.wheel += run.left_actual[index] * 0.001 * vehicle.wheel_radius_m / count;
    speeds.force += run.outputs[index].bumper_force_n / count;
  }
  return speeds;
}

TEST(FieldProfile, WheelsSlipUnderAPushNearTheTractionLimit)
{
  const common::VehicleSettings vehicle;
  // A box whose ground friction is 95 % of what the tyres can push (mu m g = 0.95 x 549 N).
  const double mass = 0.95 * vehicle.maxPushForce() / (0.5 * common::kGravity);
  SimNodeSettings field;
  field.simulator.sensing.wheels = sensingProfile(SensingProfile::kField).wheels;
  const PushSpeeds slipping = push(builtinPushRoom(mass), field);
  EXPECT_NEAR(slipping.force, 0.95 * vehicle.maxPushForce(), 0.05 * vehicle.maxPushForce());
  EXPECT_GT(slipping.body, 0.05);  // the box moves
  // The drives report the wheels' speed: the command, although the body moves about 30 % slower
  // (slip ratio 0.1 x -ln(0.05)).
  EXPECT_NEAR(slipping.wheel, 0.5, 0.01);
  EXPECT_LT(slipping.body, 0.8 * slipping.wheel);
  EXPECT_NEAR(slipping.body, 0.7 * 0.5, 0.05);

  // The same push without the tyre model: only the speed controller's own slip (6.5 cm/s).
  const PushSpeeds rigid = push(builtinPushRoom(mass), SimNodeSettings{});
  EXPECT_GT(rigid.body, 0.8 * rigid.wheel);

  // At the traction limit (a box too heavy to move) the wheels spin and the body stands.
  const PushSpeeds stalled = push(builtinPushRoom(200.0), field);
  EXPECT_NEAR(stalled.body, 0.0, 0.01);
  EXPECT_NEAR(stalled.wheel, 0.5, 0.01);
  EXPECT_NEAR(stalled.force, vehicle.maxPushForce(), 0.03 * vehicle.maxPushForce());
}

TEST(FieldProfile, ALightPushBarelySlips)
{
  SimNodeSettings field;
  field.simulator.sensing.wheels = sensingProfile(SensingProfile::kField).wheels;
  // 20 kg at mu 0.5: 98 N, 18 % of the traction limit: slip ratio 0.1 x -ln(0.82) = 2 %.
  const PushSpeeds light = push(builtinPushRoom(20.0), field);
  EXPECT_GT(light.force, 80.0);
  EXPECT_GT(light.body, 0.96 * light.wheel);
}

}  // namespace
}  // namespace ifar::sim::testing
