// The GPPC any-angle maps in ../shared/data: every query of each .scen file, exact to a relative 1e-9
// (the files give 9 decimals). AcrosstheCape's lengths are GPPC's own, the gppc-extra ones Polyanya's on
// the same rules, with both search snapshots: the planner's (every bend) and the one of a complete graph
// (only bends that wrap a corner). Skipped with a message when the data is absent.

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/grid_map/readers.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace ifar::graph {
namespace {

constexpr double kRelativeTolerance = 1e-9;

/// Plans every query of `relative_path`'s .scen file and expects `query_count` of them, each exact.
void expectEveryQueryExact(const std::string& relative_path, std::size_t query_count)
{
  const std::string map_path = std::string(IFAR_SHARED_DATA) + "/" + relative_path;
  const std::string scen_path = map_path + ".scen";
  if (!std::ifstream(map_path) || !std::ifstream(scen_path)) {
    GTEST_SKIP() << "shared data absent: " << map_path << " (.scen)";
  }
  const auto map = grid_map::readMovingAiMap(map_path);
  ASSERT_TRUE(map.ok()) << map.error;
  const auto scenarios = grid_map::readMovingAiScenarios(scen_path);
  ASSERT_TRUE(scenarios.ok()) << scenarios.error;
  ASSERT_EQ(scenarios.scenarios.size(), query_count);
  const PriorMap prior = buildPriorMap(map.map, 0.0);
  for (const bool complete : {false, true}) {
    const SearchGraph graph = complete ? SearchGraph::fromCompleteGraph(prior.graph, prior.obstacles)
                                       : SearchGraph::fromDvGraph(prior.graph);
    SearchScratch scratch;
    std::size_t exact = 0;
    for (std::size_t index = 0; index < scenarios.scenarios.size(); ++index) {
      const auto& scenario = scenarios.scenarios[index];
      const auto result = findPath(graph, prior.obstacles, scenario.start, scenario.goal, scratch, {}, {},
                                   InsideObstacle::Refuse);
      ASSERT_EQ(result.status, SearchStatus::Found)
          << (complete ? "complete" : "planner") << " snapshot, query " << index << " from ("
          << scenario.start.x() << ", " << scenario.start.y() << ") to (" << scenario.goal.x() << ", "
          << scenario.goal.y() << ")";
      const double tolerance = kRelativeTolerance * scenario.optimal_length;
      EXPECT_NEAR(result.length, scenario.optimal_length, tolerance)
          << (complete ? "complete" : "planner") << " snapshot, query " << index;
      exact += std::abs(result.length - scenario.optimal_length) <= tolerance ? 1 : 0;
    }
    EXPECT_EQ(exact, query_count) << (complete ? "complete" : "planner") << " snapshot";
  }
}

TEST(Gppc, AcrossTheCapeOptimalLengths)
{
  expectEveryQueryExact("gppc/AcrosstheCape.map", 201);
}

TEST(Gppc, Den520dExact)
{
  expectEveryQueryExact("gppc-extra/den520d.map", 888);
}

TEST(Gppc, ArcticStationExact)
{
  expectEveryQueryExact("gppc-extra/ArcticStation.map", 4100);
}

TEST(Gppc, NightshadeExact)
{
  expectEveryQueryExact("gppc-extra/Nightshade.map", 3440);
}

}  // namespace
}  // namespace ifar::graph
