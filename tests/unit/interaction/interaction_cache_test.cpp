#include "planner/interaction/interaction_cache.hpp"

#include <algorithm>
#include <cstddef>

#include <gtest/gtest.h>

#include "testing/interaction_scenes.hpp"

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

// The layer traces outlines on 0.15 m cells: with nothing moved, a side of the box comes out a cell
// further now and then (range noise or pose jitter puts a return over a cell border). Two sides a cell out
// move the centroid 0.11 m and add 23 % area: the raster's doing, not the object's.
TEST(InteractionCacheTest, AnOutlineACellOutOnTheRasterItWasTracedOnReusesThePlans)
{
  const double cell = 0.15;
  InteractionCache exact(defaultSettings());
  InteractionCache traced(defaultSettings(), cell);
  const LocalScene scene = test::doorwayScene();
  const ObjectPhysics physics{0.4, 20.0};
  bool replanned = false;
  exact.interactionsFor(5, scene, 0, physics, replanned);
  traced.interactionsFor(5, scene, 0, physics, replanned);
  ASSERT_TRUE(replanned);

  LocalScene noisy = scene;
  noisy.movable[0] = test::rectangle(-0.6, -0.8 - cell, 0.6 + cell, 0.8);
  EXPECT_TRUE(exact.stale(5, noisy, 0, physics));
  EXPECT_FALSE(traced.stale(5, noisy, 0, physics));

  // Moved by two cells, or twice its area (a second box against it): planned again.
  LocalScene moved = scene;
  moved.movable[0] = test::rectangle(-0.6 + 2 * cell, -0.8, 0.6 + 2 * cell, 0.8);
  EXPECT_TRUE(traced.stale(5, moved, 0, physics));
  LocalScene doubled = scene;
  doubled.movable[0] = test::rectangle(-0.6, -0.8, 1.8, 0.8);
  EXPECT_TRUE(traced.stale(5, doubled, 0, physics));
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

std::size_t foundPushes(const ObjectInteractions& interactions)
{
  return static_cast<std::size_t>(
      std::count_if(interactions.plans.begin(), interactions.plans.end(),
                    [](const PairPlan& plan) { return plan.plan.status == PlanStatus::Found; }));
}

/// The doorway's box seen as a bar 7 m long (inflated) along the door's axis, centred where the box is:
/// no push clears the door. The walls inside the cache's window are the same as for the box.
LocalScene barThroughTheDoorScene()
{
  LocalScene scene = test::doorwayScene();
  scene.movable[0] = test::rectangle(-3.5, -0.8, 3.5, 0.8);
  return scene;
}

TEST(InteractionCacheTest, AViewOfTheUnmovedObjectWithFewerPushesKeepsThePlansInHand)
{
  InteractionCache cache(defaultSettings());
  const ObjectPhysics physics{0.4, 20.0};
  bool replanned = false;
  ASSERT_EQ(foundPushes(cache.interactionsFor(5, test::doorwayScene(), 0, physics, replanned)), 2U);
  // Planned on its own, the bar has no push.
  InteractionCache other(defaultSettings());
  ASSERT_EQ(foundPushes(other.interactionsFor(5, barThroughTheDoorScene(), 0, physics, replanned)), 0U);

  // Seen as the bar, the object has not moved and nothing else changed: the two pushes stay.
  const LocalScene bar = barThroughTheDoorScene();
  EXPECT_TRUE(cache.stale(5, bar, 0, physics));
  EXPECT_EQ(foundPushes(cache.interactionsFor(5, bar, 0, physics, replanned)), 2U);
  EXPECT_FALSE(replanned);
  EXPECT_FALSE(cache.stale(5, bar, 0, physics));  // that view is taken in: not planned again
  // Seen whole again: planned again, the same two pushes.
  EXPECT_EQ(foundPushes(cache.interactionsFor(5, test::doorwayScene(), 0, physics, replanned)), 2U);
  EXPECT_TRUE(replanned);

  // A bar reaching 1 m further east (centroid 0.5 m east) is an object that moved: its one push is taken.
  LocalScene moved = barThroughTheDoorScene();
  moved.movable[0] = test::rectangle(-3.5, -0.8, 4.5, 0.8);
  EXPECT_EQ(foundPushes(cache.interactionsFor(5, moved, 0, physics, replanned)), 1U);
  EXPECT_TRUE(replanned);
}

/// Plans the view `first` of the box (two pushes), then asks for the view `second`: the two pushes are
/// kept, not planned again.
void expectThePushesKept(InteractionCache& cache, const LocalScene& first, const LocalScene& second)
{
  const ObjectPhysics physics{0.4, 20.0};
  bool replanned = false;
  ASSERT_EQ(foundPushes(cache.interactionsFor(5, first, 0, physics, replanned)), 2U);
  EXPECT_EQ(foundPushes(cache.interactionsFor(5, second, 0, physics, replanned)), 2U);
  EXPECT_FALSE(replanned);
}

TEST(InteractionCacheTest, TheSurroundingsOfAKeptViewAreComparedInTheWindowThePlansWereFoundIn)
{
  // A wall 5 m east of the door: outside the box's window (its bounds grown by 3 m), inside the bar's.
  LocalScene box = test::doorwayScene();
  box.background.push_back(test::rectangle(5.0, -1.0, 6.0, 1.0));
  LocalScene bar = barThroughTheDoorScene();
  bar.background = box.background;
  InteractionCache cache(defaultSettings());
  // The bar's longer outline takes in 2 m^2 more wall; where the pushes were found, nothing changed.
  expectThePushesKept(cache, box, bar);
}

TEST(InteractionCacheTest, ANeighbouringObjectSeenInPartDoesNotDropThePlansInHand)
{
  // A second object 2 m up-left of the door, inside the box's window. Seen whole (1 m^2) with the box,
  // then seen by one face (0.3 m^2) while the box is seen as the bar: the vehicle came closer, nothing
  // moved. Its outline changes with the view as the box's does, so the two pushes stay.
  LocalScene box = test::doorwayScene();
  box.movable.push_back(test::rectangle(-3.0, 2.0, -2.0, 3.0));
  LocalScene bar = barThroughTheDoorScene();
  bar.movable.push_back(test::rectangle(-3.0, 2.0, -2.7, 3.0));
  InteractionCache cache(defaultSettings());
  expectThePushesKept(cache, box, bar);
  // The neighbour still counts for whether a view is new: seen whole again beside the bar, it is.
  LocalScene bar_beside_whole = bar;
  bar_beside_whole.movable[1] = box.movable[1];
  EXPECT_TRUE(cache.stale(5, bar_beside_whole, 0, ObjectPhysics{0.4, 20.0}));
}

TEST(InteractionCacheTest, FewerPushesAreTakenWithNewSurroundingsNewPhysicsOrAfterInvalidate)
{
  const ObjectPhysics physics{0.4, 20.0};
  bool replanned = false;
  const auto planned_box = [&physics, &replanned]() {
    InteractionCache cache(defaultSettings());
    cache.interactionsFor(5, test::doorwayScene(), 0, physics, replanned);
    return cache;
  };
  // A new obstacle (1 m^2) in the window the box's plans were found in.
  LocalScene walled = barThroughTheDoorScene();
  walled.background.push_back(test::rectangle(-3.0, -3.0, -2.0, -2.0));
  InteractionCache cache = planned_box();
  EXPECT_EQ(foundPushes(cache.interactionsFor(5, walled, 0, physics, replanned)), 0U);
  EXPECT_TRUE(replanned);
  // A new physics estimate (AFFORDANCE).
  cache = planned_box();
  EXPECT_EQ(
      foundPushes(cache.interactionsFor(5, barThroughTheDoorScene(), 0, ObjectPhysics{0.4, 25.0}, replanned)),
      0U);
  EXPECT_TRUE(replanned);
  // Invalidated (the touch said the estimate was wrong).
  cache = planned_box();
  cache.invalidate(5);
  EXPECT_EQ(foundPushes(cache.interactionsFor(5, barThroughTheDoorScene(), 0, physics, replanned)), 0U);
  EXPECT_TRUE(replanned);
}

}  // namespace
}  // namespace ifar::interaction
