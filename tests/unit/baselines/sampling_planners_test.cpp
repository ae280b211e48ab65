#include "bench/baselines/sampling_planners.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace ifar::baselines {
namespace {

using grid_map::Cell;
using grid_map::GridMap;

// 20 m x 12 m, 1 m cells, a 4 m x 6 m block in the middle between start and goal.
GridMap blockMap()
{
  GridMap map(20, 12, 1.0, geometry::Point::Zero(), Cell::Free);
  for (int y = 3; y < 9; ++y) {
    for (int x = 8; x < 12; ++x) {
      map.set(x, y, Cell::Blocked);
    }
  }
  return map;
}

TEST(ExactCollision, RejectsGrazingThroughWallAcceptsAlongEdge)
{
  const graph::PriorMap prior = graph::buildPriorMap(blockMap(), 0.0);
  const graph::ObstacleSet& obstacles = prior.obstacles;
  // Along the block's bottom side (y = 3) and touching its corners: free.
  EXPECT_TRUE(obstacles.visible(geometry::Point(2.0, 3.0), geometry::Point(18.0, 3.0)));
  // A hair inside the bottom side: enters the block.
  EXPECT_FALSE(obstacles.visible(geometry::Point(2.0, 3.0), geometry::Point(18.0, 3.01)));
  // Corner to opposite corner: touches the boundary only at its ends, yet crosses the inside.
  EXPECT_FALSE(obstacles.visible(geometry::Point(8.0, 3.0), geometry::Point(12.0, 9.0)));
  // Clipping a corner by a little: rejected; passing it by a little: accepted.
  EXPECT_FALSE(obstacles.visible(geometry::Point(7.0, 2.0), geometry::Point(9.0, 4.01)));
  EXPECT_TRUE(obstacles.visible(geometry::Point(7.0, 2.0), geometry::Point(9.1, 2.99)));
}

class SamplingPlannerTest : public ::testing::TestWithParam<SamplingAlgorithm> {};

TEST_P(SamplingPlannerTest, FindsPathWithinFactorOfOptimum)
{
  seedSamplingPlanners(7);
  const graph::PriorMap prior = graph::buildPriorMap(blockMap(), 0.0);
  const graph::SearchGraph search_graph = graph::SearchGraph::fromDvGraph(prior.graph);
  graph::SearchScratch scratch;
  const geometry::Point start(2.0, 6.0);
  const geometry::Point goal(18.0, 6.0);
  const graph::SearchResult optimum = graph::findPath(search_graph, prior.obstacles, start, goal, scratch);
  ASSERT_EQ(optimum.status, graph::SearchStatus::Found);
  // Around the block: 2 * (sqrt(6^2 + 3^2)) + 4.
  EXPECT_NEAR(optimum.length, 2.0 * std::sqrt(45.0) + 4.0, 1e-9);

  SamplingSettings settings;
  settings.time_cap_s = 5.0;
  const BaselineResult result =
      planSampling(GetParam(), prior.obstacles, start, goal, optimum.length, settings);
  ASSERT_EQ(result.status, BaselineStatus::Solved) << result.reason;
  EXPECT_GE(result.length, optimum.length - 1e-9);
  EXPECT_LE(result.length, 1.5 * optimum.length + 1e-9);
  EXPECT_LT(result.milliseconds, 5000.0);
  ASSERT_GE(result.path.size(), 2u);
  EXPECT_NEAR((result.path.front() - start).norm(), 0.0, 1e-9);
  EXPECT_NEAR((result.path.back() - goal).norm(), 0.0, 1e-6);
  for (std::size_t index = 1; index < result.path.size(); ++index) {
    EXPECT_TRUE(prior.obstacles.visible(result.path[index - 1], result.path[index])) << "segment " << index;
  }
}

TEST_P(SamplingPlannerTest, RejectsBlockedStartAndTimesOutOnSealedGoal)
{
  GridMap map = blockMap();
  // Seal the goal's room: a wall across the map at x = 15.
  for (int y = 0; y < 12; ++y) {
    map.set(15, y, Cell::Blocked);
  }
  const graph::PriorMap prior = graph::buildPriorMap(map, 0.0);
  SamplingSettings settings;
  settings.time_cap_s = 0.2;
  const BaselineResult blocked = planSampling(GetParam(), prior.obstacles, geometry::Point(10.0, 6.0),
                                              geometry::Point(2.0, 2.0), 10.0, settings);
  EXPECT_EQ(blocked.status, BaselineStatus::InvalidStart);
  const BaselineResult sealed = planSampling(GetParam(), prior.obstacles, geometry::Point(2.0, 6.0),
                                             geometry::Point(18.0, 6.0), 16.0, settings);
  EXPECT_EQ(sealed.status, BaselineStatus::Timeout);
  EXPECT_TRUE(std::isnan(sealed.length));
  EXPECT_NE(sealed.reason.find("no path"), std::string::npos) << sealed.reason;
}

INSTANTIATE_TEST_SUITE_P(Planners, SamplingPlannerTest,
                         ::testing::Values(SamplingAlgorithm::RrtStar, SamplingAlgorithm::BitStar),
                         [](const ::testing::TestParamInfo<SamplingAlgorithm>& param_info) {
                           return std::string(param_info.param == SamplingAlgorithm::RrtStar ? "RrtStar"
                                                                                             : "BitStar");
                         });

}  // namespace
}  // namespace ifar::baselines
