// The --json summary line: exact text for a known summary, escaping, and no NaN in JSON.

#include "system/summary_json.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace ifar::runner {
namespace {

TEST(RunnerSummaryJson, ExactLine)
{
  RunSummary summary;
  summary.arrived = true;
  summary.reason = "arrived";
  summary.distance_m = 23.4567;
  summary.sim_time_s = 41.2;
  summary.wall_time_s = 12.5;
  summary.pushes = 1;
  summary.replans = 2;
  summary.affordance_updates = 3;
  summary.blocked_passages = 1;
  summary.escalations = 2;
  summary.goal_distance_m = 0.42;
  summary.planner_frame = FrameTimes{103, 4.1, 9.75, 12.0};
  summary.interaction = FrameTimes{103, 0.0, 2.5, 140.9};
  summary.stages = StageFrameTimes{FrameTimes{103, 2.0, 6.5, 7.0}, FrameTimes{103, 0.5, 1.25, 1.5},
                                   FrameTimes{103, 0.25, 0.5, 0.75}, FrameTimes{103, 0.125, 0.375, 2.0}};
  summary.undecided_saturated_pushes = 1;
  summary.longest_saturated_push_s = 6.25;
  summary.trajectory = {geometry::Pose2{1.0, 2.0, 0.0}};
  summary.routes = 4;
  summary.routes_switched = 1;
  summary.losses.valid = true;
  summary.losses.achievable_m = 21.0;
  summary.losses.remaining_m = 0.42;
  summary.losses.excess_m = 2.8767;
  summary.losses.buckets = LossBuckets{0.5, 0.25, 1.0, -0.125, 1.0, 0.2517};
  EXPECT_EQ(
      summaryJson(summary),
      "{\"arrived\":true,\"reason\":\"arrived\",\"distance_m\":23.457,\"time_s\":41.200,\"pushes\":1,"
      "\"replans\":2,\"affordance_updates\":3,\"blocked_passages\":1,\"escalations\":2,"
      "\"goal_distance_m\":0.420,\"wall_time_s\":12.500,\"planner_frame_ms\":{\"frames\":103,\"median\":4."
      "100,\"p99\":9.750,\"max\":12.000},"
      "\"interaction_ms\":{\"frames\":103,\"median\":0.000,\"p99\":2.500,\"max\":140.900},"
      "\"stage_ms\":{\"perception\":{\"frames\":103,\"median\":2.000,\"p99\":6.500,\"max\":7.000},"
      "\"local_graph\":{\"frames\":103,\"median\":0.500,\"p99\":1.250,\"max\":1.500},"
      "\"merge\":{\"frames\":103,\"median\":0.250,\"p99\":0.500,\"max\":0.750},"
      "\"search\":{\"frames\":103,\"median\":0.125,\"p99\":0.375,\"max\":2.000}},"
      "\"undecided_saturated_pushes\":1,\"longest_saturated_push_s\":6.250,\"routes\":4,\"routes_switched\":"
      "1,"
      "\"losses\":{\"valid\":true,\"achievable_m\":21.000,\"remaining_m\":0.420,\"excess_m\":2.877,"
      "\"exploring_m\":0.500,\"attempts_m\":0.250,\"route_switches_m\":1.000,\"route_choice_m\":-0.125,"
      "\"execution_m\":1.000,\"push_overhead_m\":0.252},\"legs\":[]}");
  // A leg per goal: where it was, whether it was reached, its distance, time and own account.
  GoalLeg leg;
  leg.goal = geometry::Point(8.0, 26.0);
  leg.arrived = true;
  leg.distance_m = 23.5612;
  leg.sim_time_s = 45.8;
  summary.legs = {leg};
  const std::string line = summaryJson(summary);
  EXPECT_NE(
      line.find(
          ",\"legs\":[{\"goal\":[8.000,26.000],\"arrived\":true,\"distance_m\":23.561,\"time_s\":45.800,"
          "\"losses\":{\"valid\":false,\"problem\":\"\"}}]}"),
      std::string::npos)
      << line;
}

TEST(RunnerSummaryJson, ReasonIsEscapedAndNonFiniteIsNull)
{
  RunSummary summary;
  summary.reason = "stopped: \"path\"\\\n\x01";
  summary.distance_m = std::numeric_limits<double>::quiet_NaN();
  const std::string line = summaryJson(summary);
  EXPECT_NE(line.find("\"reason\":\"stopped: \\\"path\\\"\\\\\\n\\u0001\""), std::string::npos) << line;
  EXPECT_NE(line.find("\"distance_m\":null"), std::string::npos) << line;
  EXPECT_NE(line.find("\"arrived\":false"), std::string::npos) << line;
  // No planner frame ran: its times are unknown, not zero.
  EXPECT_NE(line.find("\"planner_frame_ms\":{\"frames\":0,\"median\":null,\"p99\":null,\"max\":null}"),
            std::string::npos)
      << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
  // Not accounted: says why, no numbers.
  EXPECT_NE(line.find("\"losses\":{\"valid\":false,\"problem\":\"\"}"), std::string::npos) << line;
}

}  // namespace
}  // namespace ifar::runner
