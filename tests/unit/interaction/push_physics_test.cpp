// Physics agreement with the simulator's Box2D world: a push the stable-push model calls stable keeps
// the box on the bumper; an arc 30 % tighter than rho_min does not.

#include <cmath>

#include <gtest/gtest.h>

#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/stable_push.hpp"
#include "sim/physics/physics_world.hpp"
#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;

constexpr double kBoxHalf = 0.3;
constexpr double kMass = 20.0;
constexpr double kGroundFriction = 0.4;

sim::World boxWorld()
{
  sim::World world;
  world.name = "push_physics_test";
  world.bounds_min = Point(-5.0, -10.0);
  world.bounds_max = Point(10.0, 10.0);
  sim::MovableObject box;
  box.id = 1;
  box.name = "box";
  box.outline = test::rectangle(-kBoxHalf, -kBoxHalf, kBoxHalf, kBoxHalf);
  box.pose = geometry::Pose2{0.45 + 0.02 + kBoxHalf, 0.0, 0.0};  // 2 cm in front of the bumper
  box.mass_kg = kMass;
  box.ground_friction = kGroundFriction;
  world.objects.push_back(box);
  world.start = geometry::Pose2{0.0, 0.0, 0.0};
  return world;
}

struct PushOutcome {
  double box_travel_m = 0.0;
  double largest_relative_heading_rad = 0.0;  ///< box heading minus vehicle heading
  double largest_contact_drift_m = 0.0;       ///< box centre sideways in the vehicle frame
};

PushOutcome push(double linear, double angular, double seconds)
{
  const common::VehicleSettings vehicle;
  sim::physics::PhysicsWorld physics(boxWorld(), vehicle, sim::physics::PhysicsSettings{});
  const geometry::Pose2 start = physics.objectStates().front().pose;
  PushOutcome outcome;
  physics.setVelocityCommand(linear, angular);
  while (physics.timeSeconds() < seconds) {
    physics.step();
    const geometry::Pose2 box = physics.objectStates().front().pose;
    const geometry::Pose2 car = physics.vehicleState().pose;
    if ((box.position() - start.position()).norm() < 0.05) {
      continue;  // not in contact yet
    }
    outcome.largest_relative_heading_rad = std::max(outcome.largest_relative_heading_rad,
                                                    std::abs(geometry::wrapAngle(box.heading - car.heading)));
    outcome.largest_contact_drift_m =
        std::max(outcome.largest_contact_drift_m, std::abs(car.inverseTransform(box.position()).y()));
  }
  outcome.box_travel_m = (physics.objectStates().front().pose.position() - start.position()).norm();
  return outcome;
}

TEST(PushPhysicsTest, StableStraightPushKeepsTheBoxOnTheBumper)
{
  const PushOutcome outcome = push(0.3, 0.0, 8.0);
  EXPECT_GT(outcome.box_travel_m, 2.0);
  EXPECT_LT(outcome.largest_relative_heading_rad, 5.0 * M_PI / 180.0);
  EXPECT_LT(outcome.largest_contact_drift_m, 0.05);
}

TEST(PushPhysicsTest, StableArcHoldsAndTighterArcDoesNot)
{
  const PusherSettings pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  const geometry::Polygon footprint = test::rectangle(-kBoxHalf, -kBoxHalf, kBoxHalf, kBoxHalf);
  const auto options = edgePushOptions(
      footprint, pusher, ellipsoidalLimitSurface(footprint, ObjectPhysics{kGroundFriction, kMass}));
  ASSERT_TRUE(options[3].straight);  // left face, pushed towards +x
  const double rho_min = options[3].left_radius_m;
  ASSERT_TRUE(std::isfinite(rho_min));

  const PushOutcome stable = push(0.3, 0.3 / rho_min, 8.0);
  EXPECT_GT(stable.box_travel_m, 1.5);
  EXPECT_LT(stable.largest_relative_heading_rad, 5.0 * M_PI / 180.0);

  // Box2D agrees with the model near the boundary: at 0.7 rho_min the box already turns off the bumper.
  const PushOutcome tight = push(0.3, 0.3 / (0.7 * rho_min), 8.0);
  EXPECT_GT(tight.largest_relative_heading_rad, 5.0 * M_PI / 180.0);
}

}  // namespace
}  // namespace ifar::interaction
