#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "bench/scenarios/clear_pairs.hpp"
#include "bench/scenarios/scenario_maps.hpp"
#include "tests/unit/scenarios/test_worlds.hpp"

namespace ifar::scenarios {
namespace {

/// A 20 m x 12 m room whose south strip is a corridor 1.6 m wide (every point of it within 0.8 m of a
/// wall) behind a wall from x = 0 to 17, and two pillars in the room: much of the free space is nearer
/// than 1 m to something.
sim::World roomWithCorridorAndPillars()
{
  sim::World world;
  world.name = "corridor_room";
  world.source = "test";
  world.obstacles = {
      {"south", test::box(0.0, 0.0, 20.0, 0.2), 2.0, 0.2},
      {"north", test::box(0.0, 11.8, 20.0, 12.0), 2.0, 0.2},
      {"west", test::box(0.0, 0.2, 0.2, 11.8), 2.0, 0.2},
      {"east", test::box(19.8, 0.2, 20.0, 11.8), 2.0, 0.2},
      {"corridor_wall", test::box(0.2, 1.8, 17.0, 2.0), 2.0, 0.2},
      {"pillar_west", test::box(6.0, 6.0, 6.6, 6.6), 2.0, 0.2},
      {"pillar_east", test::box(13.0, 5.0, 13.6, 8.0), 2.0, 0.2},
  };
  world.start = {3.0, 9.0, 0.0};
  world.goals = {{"goal_0", geometry::Point(17.0, 9.0)}};
  sim::updateBounds(world);
  return world;
}

/// Distance from `point` to the nearest obstacle of the world as drawn (not rasterised); 0 inside one.
double trueClearance(const sim::World& world, const geometry::Point& point)
{
  double nearest = std::numeric_limits<double>::infinity();
  for (const sim::StaticObstacle& obstacle : world.obstacles) {
    if (geometry::containsPoint(obstacle.outline, point)) {
      return 0.0;
    }
    nearest = std::min(nearest, geometry::distanceToBoundary(obstacle.outline, point));
  }
  return nearest;
}

ClearPairSettings settingsFor(std::uint64_t seed, int count)
{
  ClearPairSettings settings;
  settings.seed = seed;
  settings.count = count;
  settings.min_optimal = 8.0;
  return settings;
}

using Pair = std::pair<std::pair<double, double>, std::pair<double, double>>;

Pair key(const Task& task)
{
  return {{task.start.x(), task.start.y()}, {task.goal.x(), task.goal.y()}};
}

TEST(ClearPairs, BothEndsAreAtLeastOneMetreFromTheNearestObstacle)
{
  const sim::World world = roomWithCorridorAndPillars();
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  const std::vector<Task> pairs = sampleClearPairs(world, maps, settingsFor(1, 12));
  ASSERT_EQ(pairs.size(), 12u);
  for (const Task& pair : pairs) {
    EXPECT_GE(trueClearance(world, pair.start), 1.0) << pair.id;
    EXPECT_GE(trueClearance(world, pair.goal), 1.0) << pair.id;
    EXPECT_GT(pair.optimal, 8.0) << pair.id;
    EXPECT_TRUE(std::isfinite(pair.achievable)) << pair.id << ": no known-map path";
    EXPECT_FALSE(pair.from_world);
  }
  // The map does exercise the limit: with the vehicle's half diagonal instead, ends nearer than 1 m occur.
  ClearPairSettings looser = settingsFor(1, 12);
  looser.min_clearance_m = 0.6;
  double closest = std::numeric_limits<double>::infinity();
  for (const Task& pair : sampleClearPairs(world, maps, looser)) {
    closest = std::min({closest, trueClearance(world, pair.start), trueClearance(world, pair.goal)});
  }
  EXPECT_LT(closest, 1.0);
}

TEST(ClearPairs, TheSameSeedGivesTheSamePairs)
{
  const sim::World world = roomWithCorridorAndPillars();
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  const std::vector<Task> first = sampleClearPairs(world, maps, settingsFor(2, 6));
  const std::vector<Task> second = sampleClearPairs(world, maps, settingsFor(2, 6));
  ASSERT_EQ(first.size(), 6u);
  ASSERT_EQ(second.size(), first.size());
  for (std::size_t index = 0; index < first.size(); ++index) {
    EXPECT_EQ(first[index].id, "t" + std::to_string(index));
    EXPECT_EQ(key(first[index]), key(second[index]));
    EXPECT_EQ(first[index].optimal, second[index].optimal);
  }
}

TEST(ClearPairs, SuiteSeedsTakeDisjointBlocksOfOneStream)
{
  const sim::World world = roomWithCorridorAndPillars();
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  std::set<Pair> seen;
  for (const std::uint64_t seed : {1, 2, 3}) {
    const std::vector<Task> pairs = sampleClearPairs(world, maps, settingsFor(seed, 5));
    ASSERT_EQ(pairs.size(), 5u) << "seed " << seed;
    for (const Task& pair : pairs) {
      EXPECT_TRUE(seen.insert(key(pair)).second) << "seed " << seed << " " << pair.id << " again";
    }
  }
  // Seed 2's pairs are the second block: what seed 1 would draw after its own.
  const std::vector<Task> two_blocks = sampleClearPairs(world, maps, settingsFor(1, 10));
  const std::vector<Task> second = sampleClearPairs(world, maps, settingsFor(2, 5));
  ASSERT_EQ(two_blocks.size(), 10u);
  ASSERT_EQ(second.size(), 5u);
  for (std::size_t index = 0; index < second.size(); ++index) {
    EXPECT_EQ(key(second[index]), key(two_blocks[5 + index])) << index;
  }
}

}  // namespace
}  // namespace ifar::scenarios
