// runGppcMap and its table and JSON line on the double-corner map of the graph tests (8 queries with
// hand-computed lengths), on a copy with wrong and impossible queries, and on a missing file.

#include "bench/search_comparison/gppc_suite.hpp"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace ifar::bench {
namespace {

const std::string kMap = std::string(IFAR_GRAPH_TEST_DATA) + "/double_corner.map";

TEST(GppcSuite, EveryQueryOfTheDoubleCornerMapIsExact)
{
  const GppcMapResult result = runGppcMap(kMap);
  ASSERT_TRUE(result.error.empty()) << result.error;
  EXPECT_EQ(result.map, "double_corner");
  EXPECT_EQ(result.width, 5);
  EXPECT_EQ(result.height, 5);
  EXPECT_EQ(result.queries, 8u);
  EXPECT_EQ(result.exact, 8u);
  EXPECT_TRUE(result.misses.empty());
  // The .scen rounds to 9 decimals; the worst is sqrt(2) given as 1.414213562.
  EXPECT_NEAR(result.worst_relative_error, (std::sqrt(2.0) - 1.414213562) / 1.414213562, 1e-15);
  EXPECT_EQ(result.vertices, 6u);  // the convex corners of the two blocked cells, not the pinch
  EXPECT_EQ(result.edges, 6u);
  EXPECT_GT(result.graph_mb, 0.0);
  EXPECT_LE(result.median_us, result.p99_us);
  EXPECT_LE(result.p99_us, result.max_us);
  EXPECT_GT(result.wall_median_us, 0.0);
  EXPECT_LE(result.wall_median_us, result.wall_p99_us);
  const std::string table = gppcTable({result});
  EXPECT_NE(table.find("| double_corner | 5x5 | 8 | 8 | "), std::string::npos) << table;
  EXPECT_EQ(table.find("Not exact"), std::string::npos) << table;
  const std::string line = gppcJsonLine(result);
  EXPECT_EQ(line.rfind("{\"map\": \"double_corner\", \"width\": 5, \"height\": 5, \"queries\": 8, \"found\": "
                       "8, \"exact\": 8, ",
                       0),
            0u)
      << line;
  EXPECT_NE(line.find("\"not_exact\": []}"), std::string::npos) << line;
}

TEST(GppcSuite, WrongLengthsAndRefusedQueriesAreListed)
{
  const std::string folder = ::testing::TempDir();
  const std::string map = folder + "/gppc_suite_misses.map";
  std::ofstream(map) << std::ifstream(kMap).rdbuf();
  // Query 0 right, query 1 with a wrong length, query 2 with its goal off the map (refused).
  std::ofstream(map + ".scen") << "version 1\n"
                               << "0\tm\t5\t5\t2\t2\t3\t3\t1.414213562\n"
                               << "0\tm\t5\t5\t2\t2\t1\t1\t4.000001000\n"
                               << "0\tm\t5\t5\t2\t2\t9\t9\t3.000000000\n";
  const GppcMapResult result = runGppcMap(map);
  ASSERT_TRUE(result.error.empty()) << result.error;
  EXPECT_EQ(result.queries, 3u);
  EXPECT_EQ(result.exact, 1u);
  ASSERT_EQ(result.misses.size(), 2u);
  EXPECT_EQ(result.misses[0].index, 1u);
  EXPECT_EQ(result.misses[0].status, "found");
  EXPECT_DOUBLE_EQ(result.misses[0].length, 4.0);
  EXPECT_DOUBLE_EQ(result.misses[0].expected, 4.000001);
  EXPECT_NEAR(result.worst_relative_error, 1e-6 / 4.000001, 1e-15);  // over the queries found
  EXPECT_EQ(result.misses[1].index, 2u);
  EXPECT_EQ(result.misses[1].status, "goal_off_map");
  EXPECT_TRUE(std::isnan(result.misses[1].length));
  const std::string table = gppcTable({result});
  EXPECT_NE(
      table.find("Not exact: gppc_suite_misses query 1: found, length 4.000000000, expected 4.000001000"),
      std::string::npos)
      << table;
  EXPECT_NE(table.find("query 2: goal_off_map, length null"), std::string::npos) << table;
  EXPECT_NE(gppcJsonLine(result).find(
                "{\"index\": 2, \"status\": \"goal_off_map\", \"length\": null, \"expected\": 3.000000000}"),
            std::string::npos);
}

TEST(GppcSuite, AMissingMapIsAnErrorNamingIt)
{
  const GppcMapResult result = runGppcMap("/nonexistent/nowhere.map");
  EXPECT_NE(result.error.find("/nonexistent/nowhere.map"), std::string::npos) << result.error;
  EXPECT_EQ(result.queries, 0u);
  EXPECT_EQ(gppcJsonLine(result).rfind("{\"map\": \"nowhere\", \"error\": ", 0), 0u);
}

}  // namespace
}  // namespace ifar::bench
