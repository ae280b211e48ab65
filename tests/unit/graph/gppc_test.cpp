// The GPPC any-angle benchmark map: every optimal length of the .scen file, within 1e-6 relative.

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/grid_map/readers.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace ifar::graph {
namespace {

TEST(Gppc, AcrossTheCapeOptimalLengths)
{
  const std::string map_path = std::string(IFAR_SHARED_DATA) + "/gppc/AcrosstheCape.map";
  const std::string scen_path = map_path + ".scen";
  if (!std::ifstream(map_path) || !std::ifstream(scen_path)) {
    GTEST_SKIP() << "shared data absent: " << map_path << " (.scen)";
  }
  const auto map = grid_map::readMovingAiMap(map_path);
  ASSERT_TRUE(map.ok()) << map.error;
  const auto scenarios = grid_map::readMovingAiScenarios(scen_path);
  ASSERT_TRUE(scenarios.ok()) << scenarios.error;
  ASSERT_EQ(scenarios.scenarios.size(), 201u);
  const PriorMap prior = buildPriorMap(map.map, 0.0);
  const SearchGraph graph = SearchGraph::fromDvGraph(prior.graph);
  SearchScratch scratch;
  int matched = 0;
  for (std::size_t index = 0; index < scenarios.scenarios.size(); ++index) {
    const auto& scenario = scenarios.scenarios[index];
    const auto result = findPath(graph, prior.obstacles, scenario.start, scenario.goal, scratch);
    ASSERT_EQ(result.status, SearchStatus::Found) << "query " << index;
    EXPECT_FALSE(result.start_snapped || result.goal_snapped) << "query " << index;
    EXPECT_NEAR(result.length, scenario.optimal_length, 1e-6 * scenario.optimal_length) << "query " << index;
    matched += std::abs(result.length - scenario.optimal_length) <= 1e-6 * scenario.optimal_length ? 1 : 0;
  }
  EXPECT_EQ(matched, 201);
}

}  // namespace
}  // namespace ifar::graph
