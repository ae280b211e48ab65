#include <cmath>

#include <gtest/gtest.h>

#include "bench/scenarios/result_row.hpp"

namespace ifar::scenarios {
namespace {

TEST(Spl, FailureScoresZero)
{
  EXPECT_EQ(successWeightedByPathLength(false, 10.0, 10.0), 0.0);
}

TEST(Spl, OptimalPathScoresOne)
{
  EXPECT_DOUBLE_EQ(successWeightedByPathLength(true, 10.0, 10.0), 1.0);
}

TEST(Spl, TwiceTheOptimumScoresHalf)
{
  EXPECT_DOUBLE_EQ(successWeightedByPathLength(true, 40.0, 80.0), 0.5);
}

TEST(Spl, ShorterThanOptimumIsCappedAtOne)
{
  // max(travelled, optimal) in the denominator: a path shorter than the optimum (e.g. a cut corner of
  // the raster) cannot score above 1.
  EXPECT_DOUBLE_EQ(successWeightedByPathLength(true, 10.0, 9.5), 1.0);
}

TEST(Spl, UnknownLengthOrOptimumScoresZero)
{
  EXPECT_EQ(successWeightedByPathLength(true, 10.0, NAN), 0.0);
  EXPECT_EQ(successWeightedByPathLength(true, 0.0, 5.0), 0.0);
  EXPECT_EQ(successWeightedByPathLength(true, NAN, 5.0), 0.0);
}

ResultRow searchRow()
{
  ResultRow row;
  row.table = "search";
  row.planner = "ours";
  row.kind = "office";
  row.world = "office2x-3+4";
  row.task = "t2";
  row.success = true;
  row.length = 95.25;
  row.optimal = 90.5;
  row.achievable = 93.0;
  row.without_pushing = 131.5;
  row.ms = 0.125;
  row.status = "solved";
  row.graph_vertices = 304;
  return row;
}

TEST(JsonLine, SearchRowHasEveryKeyInOrder)
{
  EXPECT_EQ(
      toJsonLine(searchRow()),
      "{\"table\": \"search\", \"planner\": \"ours\", \"kind\": \"office\", \"world\": \"office2x-3+4\", "
      "\"task\": \"t2\", \"success\": true, \"length\": 95.25, \"optimal\": 90.5, \"achievable\": 93, "
      "\"without_pushing\": 131.5, \"ms\": 0.125, "
      "\"status\": \"solved\", \"reason\": \"\", \"graph_vertices\": 304}");
}

TEST(JsonLine, FailureWritesNullLengthAndEscapedReason)
{
  ResultRow row = searchRow();
  row.success = false;
  row.length = NAN;
  row.ms = NAN;
  row.status = "timeout";
  row.reason = "cap \"5 s\"\nreached\\";
  EXPECT_EQ(
      toJsonLine(row),
      "{\"table\": \"search\", \"planner\": \"ours\", \"kind\": \"office\", \"world\": \"office2x-3+4\", "
      "\"task\": \"t2\", \"success\": false, \"length\": null, \"optimal\": 90.5, \"achievable\": 93, "
      "\"without_pushing\": 131.5, \"ms\": null, "
      "\"status\": \"timeout\", \"reason\": \"cap \\\"5 s\\\"\\nreached\\\\\", \"graph_vertices\": 304}");
}

TEST(JsonLine, SystemRowAddsSimulatedTimeAndPushes)
{
  ResultRow row = searchRow();
  row.table = "system";
  row.sim_time_s = 120.5;
  row.pushes = 2;
  row.frame_median_ms = 4.5;
  row.frame_p99_ms = 12.25;
  row.frame_max_ms = 30.0;
  row.interaction_max_ms = 21.0;
  row.sensing = "field";
  row.sensing_seed = 4;
  row.undecided_saturated_pushes = 3;
  row.escalations = 1;
  const std::string line = toJsonLine(row);
  EXPECT_NE(
      line.find(
          ", \"sim_time_s\": 120.5, \"pushes\": 2, \"frame_median_ms\": 4.5, \"frame_p99_ms\": "
          "12.25, \"frame_max_ms\": 30, \"interaction_max_ms\": 21, \"sensing\": \"field\", "
          "\"sensing_seed\": 4, \"undecided_saturated_pushes\": 3, \"escalations\": 1, \"excess_m\": null, "
          "\"loss_exploring_m\": null, "
          "\"loss_attempts_m\": null, \"loss_route_switches_m\": null, \"loss_route_choice_m\": null, "
          "\"loss_execution_m\": null, \"loss_push_overhead_m\": null}"),
      std::string::npos)
      << line;
  // An accounted run: the excess and its buckets.
  row.excess_m = 12.5;
  row.losses = runner::LossBuckets{1.0, 2.0, 0.5, -0.25, 9.0, 0.25};
  EXPECT_NE(toJsonLine(row).find("\"excess_m\": 12.5, \"loss_exploring_m\": 1, \"loss_attempts_m\": 2, "
                                 "\"loss_route_switches_m\": 0.5, \"loss_route_choice_m\": -0.25, "
                                 "\"loss_execution_m\": 9, \"loss_push_overhead_m\": 0.25}"),
            std::string::npos)
      << toJsonLine(row);
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace ifar::scenarios
