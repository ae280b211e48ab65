#include "planner/graph/visibility_builder.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/grid_map/boundaries.hpp"
#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph {
namespace {

/// A 60 x 60 map with scattered blocks (a fixed pseudo-random pattern), its rim included.
ObstacleSet scatteredBlocks()
{
  std::vector<std::string> rows(60, std::string(60, '.'));
  std::uint64_t state = 99;
  for (int block = 0; block < 140; ++block) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto column = static_cast<std::size_t>((state >> 33U) % 57U);
    const auto row = static_cast<std::size_t>((state >> 17U) % 57U);
    const std::size_t width = 1 + (state >> 7U) % 3U;
    for (std::size_t y = row; y < row + 2; ++y) {
      for (std::size_t x = column; x < column + width; ++x) {
        rows[y][x] = '@';
      }
    }
  }
  const grid_map::GridMap map = testing::mapFromRows(rows);
  std::vector<ObstacleLoop> loops;
  for (auto& polygon : grid_map::blockedBoundaries(map, grid_map::UnknownPolicy::AsFree)) {
    loops.push_back(ObstacleLoop{std::move(polygon), 0});
  }
  return ObstacleSet(std::move(loops), Bounds{map.cornerToWorld(0, 0), map.cornerToWorld(60, 60)});
}

TEST(VisibilityBuilder, AnyNumberOfThreadsBuildsTheSameGraph)
{
  const ObstacleSet obstacles = scatteredBlocks();
  DvGraph alone;
  const BuildStats alone_stats = addReducedVisibilityGraph(obstacles, alone, nullptr, {}, 1);
  ASSERT_GT(alone_stats.edges, 1000U);
  for (const unsigned threads : {2U, 3U, 8U}) {
    DvGraph shared;
    std::vector<double> reported;
    const BuildStats stats = addReducedVisibilityGraph(
        obstacles, shared, nullptr, [&](double done) { reported.push_back(done); }, threads);
    EXPECT_EQ(stats.corners, alone_stats.corners);
    EXPECT_EQ(stats.tangent_pairs, alone_stats.tangent_pairs);
    EXPECT_EQ(stats.edges, alone_stats.edges);
    ASSERT_EQ(shared.vertexSlots().size(), alone.vertexSlots().size());
    for (const Vertex& vertex : alone.vertexSlots()) {
      const std::vector<VisibilityLink>& expected = alone.visibilityLinks(vertex.id);
      const std::vector<VisibilityLink>& links = shared.visibilityLinks(vertex.id);
      ASSERT_EQ(links.size(), expected.size()) << "vertex " << vertex.id << ", " << threads << " threads";
      for (std::size_t index = 0; index < links.size(); ++index) {
        EXPECT_EQ(links[index].other, expected[index].other);  // the same edges in the same order
      }
    }
    ASSERT_FALSE(reported.empty());
    EXPECT_GE(reported.back(), 0.95);
    for (std::size_t index = 1; index < reported.size(); ++index) {
      EXPECT_GT(reported[index], reported[index - 1]);
    }
  }
}

}  // namespace
}  // namespace ifar::graph
