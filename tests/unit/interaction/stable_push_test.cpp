#include "planner/interaction/stable_push.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;

PusherSettings pusherWithFriction(double friction)
{
  PusherSettings pusher;
  pusher.bumper_width_m = 0.7;
  pusher.bumper_friction = friction;
  pusher.bumper_to_axle_m = 0.45;
  return pusher;
}

const geometry::Polygon kUnitSquare = test::rectangle(-0.5, -0.5, 0.5, 0.5);

TEST(LimitSurfaceTest, UnitSquareMatchesClosedForm)
{
  const LimitSurface surface = ellipsoidalLimitSurface(kUnitSquare, ObjectPhysics{0.4, 20.0});
  EXPECT_NEAR(surface.max_force_n, 0.4 * 20.0 * 9.81, 1e-9);
  // Mean distance of a unit square's points from its centre: (sqrt(2) + asinh(1)) / 6.
  EXPECT_NEAR(surface.characteristic_length_m, (std::sqrt(2.0) + std::asinh(1.0)) / 6.0, 2e-3);
  EXPECT_NEAR(surface.max_moment_nm, surface.max_force_n * surface.characteristic_length_m, 1e-9);
  EXPECT_DOUBLE_EQ(surface.pushForce(std::numeric_limits<double>::infinity()), surface.max_force_n);
  EXPECT_NEAR(surface.pushForce(surface.characteristic_length_m), surface.max_force_n / std::sqrt(2.0), 1e-9);
  EXPECT_LT(surface.pushForce(1.0), surface.max_force_n);
}

TEST(StablePushTest, CentredSquareStraightIsStableAndRadiusMatchesHandComputation)
{
  const LimitSurface surface = ellipsoidalLimitSurface(kUnitSquare, ObjectPhysics{0.4, 20.0});
  const auto options = edgePushOptions(kUnitSquare, pusherWithFriction(0.5), surface);
  ASSERT_EQ(options.size(), 4U);
  for (const EdgePushOptions& option : options) {
    EXPECT_TRUE(option.straight);
    // The far-corner friction-cone line binds: y >= 0.5 + (0.45 + 1.0) * cot(atan(0.5)) = 3.4 m.
    EXPECT_NEAR(option.left_radius_m, 3.4, 1e-9);
    EXPECT_NEAR(option.right_radius_m, 3.4, 1e-9);
    EXPECT_DOUBLE_EQ(option.straight_force_n, surface.max_force_n);
    EXPECT_LT(option.left_force_n, option.straight_force_n);
  }
  const ContactPatch& patch = options[0].patch;  // bottom edge, pushed towards +y
  EXPECT_NEAR(patch.middle.x(), 0.0, 1e-12);
  EXPECT_NEAR(patch.middle.y(), -0.5, 1e-12);
  EXPECT_NEAR(patch.push_direction.y(), 1.0, 1e-12);
  EXPECT_NEAR((patch.end - patch.start).norm(), 0.7, 1e-12);
}

TEST(StablePushTest, SmallestRadiusGrowsAsBumperFrictionFalls)
{
  const LimitSurface surface = ellipsoidalLimitSurface(kUnitSquare, ObjectPhysics{0.4, 20.0});
  double previous = 0.0;
  for (const double friction : {1.0, 0.8, 0.5, 0.3, 0.2, 0.1}) {
    const auto options = edgePushOptions(kUnitSquare, pusherWithFriction(friction), surface);
    EXPECT_TRUE(options[0].straight) << "friction " << friction;
    EXPECT_GT(options[0].left_radius_m, previous) << "friction " << friction;
    previous = options[0].left_radius_m;
  }
  EXPECT_NEAR(previous, 0.5 + 1.45 * 10.0, 1e-9);  // cot(atan(0.1)) = 10
}

TEST(StablePushTest, FrictionlessBumperHasNoStablePush)
{
  const LimitSurface surface = ellipsoidalLimitSurface(kUnitSquare, ObjectPhysics{0.4, 20.0});
  for (const EdgePushOptions& option : edgePushOptions(kUnitSquare, pusherWithFriction(0.0), surface)) {
    EXPECT_FALSE(option.pushable());
  }
}

TEST(StablePushTest, ContactFarOffCentreMakesStraightAndSomeArcsUnstable)
{
  const geometry::Polygon plank = test::rectangle(-1.5, -0.25, 1.5, 0.25);
  const LimitSurface surface = ellipsoidalLimitSurface(plank, ObjectPhysics{0.4, 20.0});
  // Bumper at the right end of the bottom edge: the centre of friction projects outside the contact.
  ContactPatch patch = contactPatch(plank, 0, 0.7);
  patch.start = Point(0.8, -0.25);
  patch.end = Point(1.5, -0.25);
  patch.middle = (patch.start + patch.end) / 2.0;
  const StableRegion region(plank, patch, 0.5, surface);
  EXPECT_FALSE(region.contains(Point(-0.45, 1e6)));
  EXPECT_FALSE(region.contains(Point(-0.45, -1e6)));
  const auto left = region.stableAlongLine(-0.45, true);
  const auto right = region.stableAlongLine(-0.45, false);
  const bool left_unbounded = !left.empty() && !std::isfinite(left.high);
  const bool right_unbounded = !right.empty() && !std::isfinite(right.low);
  EXPECT_FALSE(left_unbounded && right_unbounded);

  // The same plank pushed at the centre of its long edge is stable straight on.
  const ContactPatch centred = contactPatch(plank, 0, 0.7);
  EXPECT_NEAR(centred.middle.x(), 0.0, 1e-12);
  const StableRegion centred_region(plank, centred, 0.5, surface);
  EXPECT_TRUE(centred_region.contains(Point(-0.45, 1e6)));
  EXPECT_TRUE(centred_region.contains(Point(-0.45, -1e6)));
  // Turning about a point right behind the bumper is never stable.
  EXPECT_FALSE(centred_region.contains(Point(-0.45, 0.2)));
}

TEST(StablePushTest, PhysicsChecksRejectBadEstimates)
{
  const PusherSettings pusher = pusherWithFriction(0.5);
  EXPECT_EQ(checkPhysics(ObjectPhysics{0.4, 20.0}, pusher), PlanStatus::Found);
  EXPECT_EQ(checkPhysics(ObjectPhysics{0.0, 20.0}, pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(checkPhysics(ObjectPhysics{-0.3, 20.0}, pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(checkPhysics(ObjectPhysics{0.4, 0.0}, pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(checkPhysics(ObjectPhysics{0.4, -5.0}, pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(checkPhysics(ObjectPhysics{std::nan(""), 20.0}, pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(checkPhysics(ObjectPhysics{0.4, 20.0}, pusherWithFriction(-0.1)), PlanStatus::InvalidPhysics);
}

}  // namespace
}  // namespace ifar::interaction
