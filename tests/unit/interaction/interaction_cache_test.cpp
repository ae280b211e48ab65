#include "planner/interaction/interaction_cache.hpp"

#include <gtest/gtest.h>

#include "tests/unit/interaction/scenes.hpp"

namespace ifar::interaction {
namespace {

InteractionSettings defaultSettings()
{
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  settings.search.time_budget_s = 1.0;
  return settings;
}

TEST(InteractionCacheTest, ReplansOnlyWhenObjectSurroundingsOrAffordanceChange)
{
  InteractionCache cache(defaultSettings());
  LocalScene scene = test::doorwayScene();
  const ObjectPhysics physics{0.4, 20.0};
  bool replanned = false;
  EXPECT_EQ(cache.interactionsFor(5, scene, 0, physics, replanned).plans.size(), 2U);
  EXPECT_TRUE(replanned);
  cache.interactionsFor(5, scene, 0, physics, replanned);
  EXPECT_FALSE(replanned);

  // Perception noise of a few centimetres reuses the plans.
  for (geometry::Point& vertex : scene.movable[0]) {
    vertex.x() += 0.03;
  }
  EXPECT_FALSE(cache.stale(5, scene, 0, physics));
  // The object moved.
  for (geometry::Point& vertex : scene.movable[0]) {
    vertex.x() += 0.5;
  }
  EXPECT_TRUE(cache.stale(5, scene, 0, physics));
  scene = test::doorwayScene();
  // A new wall nearby, or a new affordance estimate.
  LocalScene walled = test::doorwayWithWallBehindScene();
  EXPECT_TRUE(cache.stale(5, walled, 0, physics));
  EXPECT_TRUE(cache.stale(5, scene, 0, ObjectPhysics{0.4, 60.0}));
  EXPECT_FALSE(cache.stale(5, scene, 0, physics));
  cache.invalidate(5);
  EXPECT_TRUE(cache.stale(5, scene, 0, physics));
  cache.interactionsFor(5, scene, 0, ObjectPhysics{0.9, 400.0}, replanned);
  EXPECT_TRUE(replanned);
  EXPECT_EQ(cache.interactionsFor(5, scene, 0, ObjectPhysics{0.9, 400.0}, replanned).plans[0].plan.status,
            PlanStatus::TooHeavy);
  EXPECT_EQ(cache.size(), 1U);
  cache.forget(5);
  EXPECT_EQ(cache.size(), 0U);
  EXPECT_TRUE(cache.stale(5, scene, 0, physics));
}

TEST(InteractionCacheTest, ObstaclesSplitDifferentlyReuseThePlans)
{
  InteractionCache cache(defaultSettings());
  const LocalScene scene = test::doorwayScene();
  const ObjectPhysics physics{0.4, 20.0};
  bool replanned = false;
  cache.interactionsFor(5, scene, 0, physics, replanned);
  ASSERT_TRUE(replanned);
  // The same walls as pieces of a raster (the planner's scene): count and pieces change, area does not.
  LocalScene pieces = scene;
  pieces.background = {test::rectangle(-0.5, 0.6, 0.5, 2.0), test::rectangle(-0.5, 2.0, 0.5, 5.0),
                       test::rectangle(-0.5, -5.0, 0.5, -3.0), test::rectangle(-0.5, -3.0, 0.5, -0.6)};
  EXPECT_FALSE(cache.stale(5, pieces, 0, physics));
  // A raster cell more or less along a wall (0.15 m x 0.15 m) is noise too.
  pieces.background.push_back(test::rectangle(0.5, 3.0, 0.65, 3.15));
  EXPECT_FALSE(cache.stale(5, pieces, 0, physics));
}

}  // namespace
}  // namespace ifar::interaction
