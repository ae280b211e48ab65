// Random and hostile input never throws and always yields a status (the daemon must survive anything
// perception produces).

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "planner/interaction/interaction_planner.hpp"
#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;
using geometry::Polygon;

Polygon randomPolygon(std::mt19937& random, double centre_range, double size)
{
  std::uniform_real_distribution<double> centre(-centre_range, centre_range);
  std::uniform_real_distribution<double> offset(-size, size);
  std::uniform_int_distribution<int> count(0, 9);
  const Point middle(centre(random), centre(random));
  Polygon polygon;
  for (int index = count(random); index > 0; --index) {
    polygon.push_back(middle + Point(offset(random), offset(random)));
  }
  return polygon;
}

TEST(InteractionRobustnessTest, RandomScenesNeverThrow)
{
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> physics_value(-0.2, 1.0);
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  settings.search.time_budget_s = 0.002;
  std::size_t found = 0;
  std::size_t splits = 0;
  for (int trial = 0; trial < 150; ++trial) {
    LocalScene scene;
    scene.movable = {randomPolygon(random, 0.5, 1.0), randomPolygon(random, 2.0, 1.0)};
    for (int wall = 0; wall < 3; ++wall) {
      scene.background.push_back(randomPolygon(random, 2.0, 2.0));
    }
    if (trial % 2 == 1) {  // mostly valid shapes, so the analysis and search run too
      scene.movable[0] = geometry::convexHull(scene.movable[0]);
      for (Polygon& wall : scene.background) {
        wall = geometry::convexHull(wall);
      }
    }
    if (trial % 10 == 0) {
      scene.background.push_back(
          {Point(0.0, 0.0), Point(std::numeric_limits<double>::quiet_NaN(), 1.0), Point(1.0, 1.0)});
    }
    const ObjectPhysics physics{physics_value(random), 40.0 * physics_value(random)};
    ObjectInteractions result;
    ASSERT_NO_THROW(result = planObjectInteractions(scene, 0, physics, settings)) << "trial " << trial;
    EXPECT_EQ(result.plans.size(), result.connectivity.pairs.size());
    splits += result.connectivity.splits ? 1U : 0U;
    for (const PairPlan& pair : result.plans) {
      if (pair.plan.status == PlanStatus::Found) {
        ++found;
        EXPECT_TRUE(std::isfinite(pair.plan.cost));
        EXPECT_GE(pair.plan.cost, 0.0);
      }
    }
  }
  RecordProperty("plans_found", static_cast<int>(found));
  RecordProperty("splits", static_cast<int>(splits));
}

TEST(InteractionRobustnessTest, HostileObjectsGiveReasons)
{
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  LocalScene scene = test::doorwayScene();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  for (const Polygon& object :
       {Polygon{}, Polygon{Point(0, 0)}, Polygon{Point(0, 0), Point(0, 0), Point(0, 0)},
        Polygon{Point(0, 0), Point(1, 0), Point(nan, 1)},
        Polygon{Point(0, 0), Point(infinity, 0), Point(0, 1)}, test::rectangle(-1e6, -1.0, 1e6, 1.0)}) {
    scene.movable = {object};
    const ObjectInteractions result = planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings);
    EXPECT_NE(result.connectivity.status, PlanStatus::Found);
    EXPECT_FALSE(result.connectivity.splits);
    EXPECT_TRUE(result.plans.empty());
  }
}

}  // namespace
}  // namespace ifar::interaction
