#include <cmath>

#include <gtest/gtest.h>

#include "bench/search_comparison/query_set.hpp"
#include "sim/world/world_raster.hpp"

namespace ifar::bench {
namespace {

sim::World wallWorld()
{
  sim::World world;
  world.name = "wall";
  world.bounds_min = geometry::Point(0.0, 0.0);
  world.bounds_max = geometry::Point(3.0, 1.5);
  // A 5 cm wall at x in [1.02, 1.07] (inside cell column 6 of 0.15 m cells: [0.90, 1.05] and 7:
  // [1.05, 1.20]), from y = 0 to 1.2: it covers no cell centre, yet must block both columns it overlaps.
  sim::StaticObstacle wall;
  wall.name = "thin_wall";
  wall.outline = {geometry::Point(1.02, 0.0), geometry::Point(1.07, 0.0), geometry::Point(1.07, 1.2),
                  geometry::Point(1.02, 1.2)};
  world.obstacles.push_back(wall);
  // A box whose sides lie exactly on cell sides: blocks exactly its 2 x 2 cells, not the neighbours.
  sim::StaticObstacle box;
  box.name = "box";
  box.outline = {geometry::Point(2.1, 0.3), geometry::Point(2.4, 0.3), geometry::Point(2.4, 0.6),
                 geometry::Point(2.1, 0.6)};
  world.obstacles.push_back(box);
  return world;
}

TEST(WorldRaster, ThinWallsBlockEveryOverlappedCellAndTouchingLeavesFree)
{
  const grid_map::GridMap map = sim::rasterizeStaticObstacles(wallWorld(), 0.15);
  ASSERT_EQ(map.width(), 20);
  ASSERT_EQ(map.height(), 10);
  for (int y = 0; y < 8; ++y) {
    EXPECT_EQ(map.at(6, y), grid_map::Cell::Blocked) << "y " << y;
    EXPECT_EQ(map.at(7, y), grid_map::Cell::Blocked) << "y " << y;
    EXPECT_EQ(map.at(5, y), grid_map::Cell::Free) << "y " << y;
    EXPECT_EQ(map.at(8, y), grid_map::Cell::Free) << "y " << y;
  }
  EXPECT_EQ(map.at(6, 8), grid_map::Cell::Free);  // the gap above the wall
  EXPECT_EQ(map.count(grid_map::Cell::Blocked), 16u + 4u);
  EXPECT_EQ(map.at(14, 2), grid_map::Cell::Blocked);
  EXPECT_EQ(map.at(15, 3), grid_map::Cell::Blocked);
  EXPECT_EQ(map.at(13, 2), grid_map::Cell::Free);
  EXPECT_EQ(map.at(16, 2), grid_map::Cell::Free);
  EXPECT_EQ(map.at(14, 4), grid_map::Cell::Free);
}

TEST(QuerySet, RandomQueriesAreSeededConnectedAndLongEnough)
{
  const grid_map::GridMap map = sim::rasterizeStaticObstacles(wallWorld(), 0.15);
  const graph::PriorMap exact = graph::buildPriorMap(map, 0.0);
  RandomQuerySettings settings;
  settings.count = 5;
  settings.seed = 3;
  settings.min_length = 1.5;
  const std::vector<Query> first =
      randomQueries(map, grid_map::UnknownPolicy::AsBlocked, exact, exact, settings);
  const std::vector<Query> second =
      randomQueries(map, grid_map::UnknownPolicy::AsBlocked, exact, exact, settings);
  ASSERT_EQ(first.size(), 5u);
  ASSERT_EQ(second.size(), 5u);
  for (std::size_t index = 0; index < first.size(); ++index) {
    EXPECT_EQ(first[index].task, "q" + std::to_string(index));
    EXPECT_EQ(first[index].start, second[index].start);
    EXPECT_EQ(first[index].goal, second[index].goal);
    EXPECT_GE(first[index].optimal, 1.5);
    EXPECT_GE(first[index].optimal, (first[index].goal - first[index].start).norm() - 1e-9);
    EXPECT_NEAR(exactOptimum(exact, first[index].start, first[index].goal), first[index].optimal, 1e-12);
  }
}

TEST(QuerySet, ExactOptimumGoesAroundTheWall)
{
  const grid_map::GridMap map = sim::rasterizeStaticObstacles(wallWorld(), 0.15);
  const graph::PriorMap exact = graph::buildPriorMap(map, 0.0);
  // From (0.5, 0.3) to (1.6, 0.3) around the wall's top corners at (0.9, 1.2) and (1.2, 1.2).
  const double expected = std::hypot(0.4, 0.9) + 0.3 + std::hypot(0.4, 0.9);
  EXPECT_NEAR(exactOptimum(exact, geometry::Point(0.5, 0.3), geometry::Point(1.6, 0.3)), expected, 1e-9);
}

}  // namespace
}  // namespace ifar::bench
