#include "sim/physics/physics_world.hpp"

#include <gtest/gtest.h>

#include "sim/simulator/builtin_worlds.hpp"

namespace ifar::sim::physics {
namespace {

struct RunSummary {
  double mean_force = 0.0;  // bumper force over the last second
  BodyState vehicle;
  BodyState box;
};

/// Drives forward at `speed` for `seconds`, then reports the last second's mean bumper force.
RunSummary driveInto(PhysicsWorld& physics, double speed, double seconds)
{
  physics.setVelocityCommand(speed, 0.0);
  const int steps = static_cast<int>(seconds / physics.settings().step_seconds);
  const int averaged = static_cast<int>(1.0 / physics.settings().step_seconds);
  RunSummary summary;
  for (int step = 0; step < steps; ++step) {
    physics.step();
    if (step >= steps - averaged) {
      summary.mean_force += physics.bumperForce() / averaged;
    }
  }
  summary.vehicle = physics.vehicleState();
  summary.box = physics.objectStates().at(0);
  return summary;
}

TEST(PhysicsWorld, FollowsVelocityCommandsInFreeSpace)
{
  const common::VehicleSettings vehicle;
  PhysicsWorld physics(builtinRoom(), vehicle, PhysicsSettings{});
  physics.setVelocityCommand(0.8, 0.0);
  for (int step = 0; step < 600; ++step) {
    physics.step();
  }
  const auto straight = physics.vehicleState();
  EXPECT_NEAR(straight.linear_velocity.x(), 0.8, 0.01);
  EXPECT_NEAR(straight.linear_velocity.y(), 0.0, 1e-3);
  // 0.8 s ramp at 1 m/s^2 (0.32 m) then 2.2 s at 0.8 m/s (1.76 m), from x = 2.
  EXPECT_NEAR(straight.pose.x, 2.0 + 0.32 + 1.76, 0.03);
  EXPECT_NEAR(physics.bumperForce(), 0.0, 1e-9);

  physics.setVelocityCommand(0.0, 1.0);
  for (int step = 0; step < 400; ++step) {
    physics.step();
  }
  const auto turning = physics.vehicleState();
  EXPECT_NEAR(turning.angular_velocity, 1.0, 0.01);
  EXPECT_NEAR(turning.linear_velocity.norm(), 0.0, 0.01);
}

TEST(PhysicsWorld, ClampsCommandsToTheVehicleLimits)
{
  const common::VehicleSettings vehicle;
  PhysicsWorld physics(builtinRoom(), vehicle, PhysicsSettings{});
  physics.setWheelSpeedCommand({5.0, 5.0});
  for (int step = 0; step < 600; ++step) {
    physics.step();
  }
  EXPECT_NEAR(physics.vehicleState().linear_velocity.norm(), vehicle.max_linear_velocity, 0.01);
  EXPECT_NEAR(physics.wheelSpeeds().left, vehicle.max_linear_velocity, 1e-9);
}

TEST(PhysicsWorld, PushingALightBoxMovesItAndItStopsWhenReleased)
{
  const common::VehicleSettings vehicle;
  // 20 kg, ground friction 0.5: 98.1 N to keep it sliding; the vehicle can push 549 N.
  PhysicsWorld physics(builtinPushRoom(20.0, 0.5), vehicle, PhysicsSettings{});
  const double box_start_x = physics.objectStates().at(0).pose.x;
  const RunSummary pushing = driveInto(physics, 0.5, 5.0);
  EXPECT_GT(pushing.box.pose.x - box_start_x, 1.0);
  EXPECT_NEAR(pushing.box.linear_velocity.x(), 0.5, 0.05);
  EXPECT_NEAR(pushing.box.pose.y, physics.vehicleState().pose.y, 0.05);
  // Sliding at constant speed the bumper carries exactly the ground friction.
  EXPECT_NEAR(pushing.mean_force, 0.5 * 20.0 * 9.81, 10.0);

  // Back off: the box is no longer pushed and friction stops it within a moment.
  physics.setVelocityCommand(-0.3, 0.0);
  for (int step = 0; step < 200; ++step) {
    physics.step();
  }
  const auto released = physics.objectStates().at(0);
  EXPECT_LT(released.linear_velocity.norm(), 1e-3);
  for (int step = 0; step < 200; ++step) {
    physics.step();
  }
  EXPECT_NEAR(physics.objectStates().at(0).pose.x, released.pose.x, 1e-4);
  EXPECT_NEAR(physics.bumperForce(), 0.0, 1e-9);
}

TEST(PhysicsWorld, PushingAHeavyBoxStallsTheVehicleAtTheTractionLimit)
{
  const common::VehicleSettings vehicle;
  // 200 kg, friction 0.5: 981 N needed, more than the 549 N the wheels can push.
  PhysicsWorld physics(builtinPushRoom(200.0, 0.5), vehicle, PhysicsSettings{});
  const double box_start_x = physics.objectStates().at(0).pose.x;
  const RunSummary pushing = driveInto(physics, 0.5, 5.0);
  EXPECT_LT(std::abs(pushing.box.pose.x - box_start_x), 0.01);
  EXPECT_LT(pushing.vehicle.linear_velocity.norm(), 0.01);
  // The vehicle is stuck with its bumper on the box face (box half side 0.3, vehicle half length 0.45).
  EXPECT_NEAR(pushing.vehicle.pose.x, box_start_x - 0.3 - 0.45, 0.02);
  EXPECT_NEAR(pushing.mean_force, vehicle.maxPushForce(), 0.02 * vehicle.maxPushForce());
}

TEST(PhysicsWorld, WallStopsTheVehicle)
{
  const common::VehicleSettings vehicle;
  PhysicsWorld physics(builtinRoom(6.0), vehicle, PhysicsSettings{});
  const RunSummary run = [&] {
    physics.setVelocityCommand(1.0, 0.0);
    for (int step = 0; step < 1200; ++step) {
      physics.step();
    }
    RunSummary summary;
    summary.vehicle = physics.vehicleState();
    return summary;
  }();
  // East wall inner face at x = 5.8; the bumper face is 0.45 ahead of the axle.
  EXPECT_NEAR(run.vehicle.pose.x, 5.8 - 0.45, 0.02);
  EXPECT_NEAR(physics.bumperForce(), vehicle.maxPushForce(), 0.05 * vehicle.maxPushForce());
}

TEST(PhysicsWorld, RejectsAnObjectWithoutArea)
{
  World world = builtinPushRoom(20.0);
  world.objects[0].outline = {geometry::Point(0, 0), geometry::Point(1, 0), geometry::Point(2, 0)};
  try {
    PhysicsWorld physics(world, common::VehicleSettings{}, PhysicsSettings{});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("object 'box' (id 1)"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ifar::sim::physics
