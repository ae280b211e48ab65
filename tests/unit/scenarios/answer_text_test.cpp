#include "bench/scenarios/answer_text.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "bench/scenarios/result_row.hpp"
#include "bench/scenarios/system_runs.hpp"

namespace ifar::scenarios {
namespace {

TEST(AnswerText, NumbersAndTextComeBackExactly)
{
  AnswerWriter writer;
  writer.number(0.1 + 0.2);
  writer.number(NAN);
  writer.number(-std::numeric_limits<double>::infinity());
  writer.number(-0.0);
  writer.number(std::numeric_limits<double>::denorm_min());
  writer.integer(-42);
  writer.flag(true);
  writer.text("12: spaces, colons\nand newlines");
  writer.text("");
  AnswerReader reader(writer.answer());
  double sum = 0.0;
  double not_a_number = 0.0;
  double minus_infinity = 0.0;
  double minus_zero = 1.0;
  double smallest = 0.0;
  std::int64_t integer = 0;
  bool flag = false;
  std::string text;
  std::string empty = "x";
  ASSERT_TRUE(reader.number(sum) && reader.number(not_a_number) && reader.number(minus_infinity) &&
              reader.number(minus_zero) && reader.number(smallest) && reader.integer(integer) &&
              reader.flag(flag) && reader.text(text) && reader.text(empty));
  EXPECT_TRUE(reader.complete());
  EXPECT_EQ(sum, 0.1 + 0.2);
  EXPECT_TRUE(std::isnan(not_a_number));
  EXPECT_EQ(minus_infinity, -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::signbit(minus_zero));
  EXPECT_EQ(smallest, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(integer, -42);
  EXPECT_TRUE(flag);
  EXPECT_EQ(text, "12: spaces, colons\nand newlines");
  EXPECT_EQ(empty, "");
}

TEST(AnswerText, WhatWasNotWrittenIsNotRead)
{
  AnswerWriter writer;
  writer.text("abc");
  const std::string shortened = writer.answer().substr(0, writer.answer().size() - 1);
  AnswerReader cut(shortened);
  std::string text;
  EXPECT_FALSE(cut.text(text));
  EXPECT_FALSE(cut.complete());

  AnswerReader wrong_kind("abc ");
  double number = 0.0;
  EXPECT_FALSE(wrong_kind.number(number));
  AnswerReader two_for_a_flag("2 ");
  bool flag = false;
  EXPECT_FALSE(two_for_a_flag.flag(flag));
  AnswerReader claims_too_much("99:abc");
  EXPECT_FALSE(claims_too_much.text(text));
}

TEST(AnswerText, ARowComesBackFieldForField)
{
  ResultRow row;
  row.table = "system";
  row.planner = "ours";
  row.kind = "willow";
  row.world = "willow";
  row.task = "t3";
  row.success = true;
  row.length = 116.7;
  row.optimal = 48.7;
  row.ms = 1.0 / 3.0;
  row.status = "arrived";
  row.reason = "";
  row.graph_vertices = 8107;
  row.sim_time_s = 254.927;
  row.pushes = 3;
  row.frame_p99_ms = 22.713;
  row.sensing_seed = 7;
  const std::optional<ResultRow> back = rowFromAnswer(toAnswer(row));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(toJsonLine(*back), toJsonLine(row));
  EXPECT_EQ(back->ms, 1.0 / 3.0);
  EXPECT_TRUE(std::isnan(back->achievable));
  EXPECT_FALSE(rowFromAnswer(toAnswer(row) + "1 ").has_value());
  EXPECT_FALSE(rowFromAnswer(toAnswer(row).substr(0, 20)).has_value());
}

TEST(AnswerText, ASystemRunComesBackWithItsTrajectory)
{
  SystemRun run;
  run.ran = true;
  run.failure_status = "timeout";
  run.reason = "runner killed after 300.0 s";
  run.distance_m = 44.0;
  run.pushes = 1;
  run.excess_m = 3.25;
  run.losses = runner::LossBuckets{0.5, 0.0, 1.0 / 3.0, -0.125, 1.5, 0.0};
  run.trajectory = {{1.0, 2.0, 0.5}, {1.1, 2.05, -3.1}};
  const std::optional<SystemRun> back = systemRunFromAnswer(toAnswer(run));
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(back->ran);
  EXPECT_FALSE(back->arrived);
  EXPECT_EQ(back->failure_status, "timeout");
  EXPECT_EQ(back->reason, run.reason);
  EXPECT_EQ(back->distance_m, 44.0);
  EXPECT_EQ(back->pushes, 1);
  EXPECT_TRUE(std::isnan(back->frame_median_ms));
  EXPECT_EQ(back->excess_m, 3.25);
  EXPECT_EQ(back->losses.route_switches_m, 1.0 / 3.0);
  EXPECT_EQ(back->losses.route_choice_m, -0.125);
  EXPECT_EQ(back->losses.execution_m, 1.5);
  ASSERT_EQ(back->trajectory.size(), 2u);
  EXPECT_EQ(back->trajectory[1].heading, -3.1);
  // A pose count the answer cannot hold is refused before anything is reserved for it.
  std::string claim = toAnswer(SystemRun{});
  claim.replace(claim.rfind("0 "), 2, "1000000000000 ");
  EXPECT_FALSE(systemRunFromAnswer(claim).has_value());
}

}  // namespace
}  // namespace ifar::scenarios
