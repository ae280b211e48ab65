// The map-scale row of ifar bench-search --gppc-suite: the repeated grid cell by cell, the seeded queries
// (free cells, reproducible), and a run without reference lengths on the double-corner map repeated.

#include "bench/search_comparison/map_scale.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bench/search_comparison/gppc_suite.hpp"

namespace ifar::bench {
namespace {

using grid_map::Cell;
using grid_map::GridMap;

const std::string kMap = std::string(IFAR_GRAPH_TEST_DATA) + "/double_corner.map";

TEST(MapScale, TheRepeatedMapCopiesTheTileCellByCell)
{
  GridMap tile(3, 2, 0.5, geometry::Point(1.0, -2.0));
  tile.set(0, 0, Cell::Blocked);
  tile.set(2, 1, Cell::Unknown);
  const GridMap map = tiledMap(tile, 7, 5);
  ASSERT_EQ(map.width(), 7);
  ASSERT_EQ(map.height(), 5);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.5);
  EXPECT_DOUBLE_EQ(map.origin().x(), 1.0);
  EXPECT_DOUBLE_EQ(map.origin().y(), -2.0);
  EXPECT_EQ(map.count(Cell::Blocked), 9u);  // x in {0, 3, 6}, y in {0, 2, 4}
  EXPECT_EQ(map.count(Cell::Unknown), 4u);  // x in {2, 5}, y in {1, 3}
  EXPECT_EQ(map.at(6, 4), Cell::Blocked);
  EXPECT_EQ(map.at(5, 3), Cell::Unknown);
  EXPECT_EQ(map.at(4, 3), Cell::Free);
  EXPECT_EQ(map.at(6, 3), Cell::Free);
  EXPECT_EQ(tiledMap(GridMap(), 2, 2).count(Cell::Blocked), 4u);
}

TEST(MapScale, SeededQueriesJoinFreeCellCentresAndRepeatWithTheSeed)
{
  GridMap map(4, 3, 1.0, geometry::Point::Zero(), Cell::Blocked);
  map.set(1, 2, Cell::Free);
  map.set(3, 0, Cell::Free);
  const auto queries = seededFreeCellQueries(map, 50, 7);
  ASSERT_EQ(queries.size(), 50u);
  bool both_cells_drawn = false;
  for (const auto& query : queries) {
    for (const geometry::Point& end : {query.start, query.goal}) {
      const bool first = end.x() == 1.5 && end.y() == 2.5;
      const bool second = end.x() == 3.5 && end.y() == 0.5;
      EXPECT_TRUE(first || second) << end.transpose();
    }
    both_cells_drawn = both_cells_drawn || query.start != query.goal;
    EXPECT_TRUE(std::isnan(query.optimal_length));
  }
  EXPECT_TRUE(both_cells_drawn);
  const auto again = seededFreeCellQueries(map, 50, 7);
  for (std::size_t index = 0; index < queries.size(); ++index) {
    EXPECT_EQ(again[index].start, queries[index].start);
    EXPECT_EQ(again[index].goal, queries[index].goal);
  }
  EXPECT_TRUE(
      seededFreeCellQueries(GridMap(2, 2, 1.0, geometry::Point::Zero(), Cell::Blocked), 5, 1).empty());
}

TEST(MapScale, ARunWithoutReferenceCountsFoundQueriesAndNamesNoneExact)
{
  const auto tile = grid_map::readMovingAiMap(kMap);
  ASSERT_TRUE(tile.ok()) << tile.error;
  const GridMap map = tiledMap(tile.map, 10, 10);
  const GppcMapResult result =
      runGppcQueries("double_corner repeated", map, seededFreeCellQueries(map, 20, 3), false);
  ASSERT_TRUE(result.error.empty());
  EXPECT_FALSE(result.reference);
  EXPECT_EQ(result.queries, 20u);
  EXPECT_EQ(result.found, 20u);  // the repeated pinches join every free cell
  EXPECT_EQ(result.exact, 0u);
  EXPECT_TRUE(result.misses.empty());
  EXPECT_TRUE(std::isnan(result.worst_relative_error));
  EXPECT_EQ(result.vertices, 24u);  // 4 copies of the two blocked cells, 6 convex corners each
  const std::string table = gppcTable({result});
  EXPECT_NE(table.find("| double_corner repeated | 10x10 | 20 | no reference, 20 found | - | "),
            std::string::npos)
      << table;
  const std::string line = gppcJsonLine(result);
  EXPECT_NE(line.find("\"queries\": 20, \"found\": 20, \"exact\": null, \"worst_relative_error\": null"),
            std::string::npos)
      << line;
}

}  // namespace
}  // namespace ifar::bench
