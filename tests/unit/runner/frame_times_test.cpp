// Per-stage frame times: each stage's samples land in its own figures, with nearest-rank percentiles.

#include "system/frame_times.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace ifar::runner {
namespace {

TEST(PlannerFrameRecordTest, EachStageKeepsItsOwnTimes)
{
  PlannerFrameRecord record;
  // 100 frames: stage k of frame i takes (k + 1) x i ms, the total 100 + i ms.
  for (int i = 1; i <= 100; ++i) {
    const double step = static_cast<double>(i);
    record.add(
        planner::StageTimings{1.0 * step, 2.0 * step, 3.0 * step, 4.0 * step, 5.0 * step, 100.0 + step});
  }
  const StageFrameTimes stages = record.stages();
  EXPECT_EQ(stages.perception.frames, 100U);
  EXPECT_DOUBLE_EQ(stages.perception.median_ms, 50.0);
  EXPECT_DOUBLE_EQ(stages.perception.p99_ms, 99.0);
  EXPECT_DOUBLE_EQ(stages.perception.max_ms, 100.0);
  EXPECT_DOUBLE_EQ(stages.local_graph.p99_ms, 198.0);
  EXPECT_DOUBLE_EQ(stages.merge.max_ms, 300.0);
  EXPECT_DOUBLE_EQ(record.interaction().median_ms, 200.0);
  EXPECT_DOUBLE_EQ(stages.search.p99_ms, 495.0);
  EXPECT_DOUBLE_EQ(record.total().p99_ms, 199.0);
  EXPECT_DOUBLE_EQ(record.total().max_ms, 200.0);
}

TEST(PlannerFrameRecordTest, NoFrameGivesUnknownTimesNotZero)
{
  const PlannerFrameRecord record;
  EXPECT_EQ(record.total().frames, 0U);
  EXPECT_TRUE(std::isnan(record.total().p99_ms));
  EXPECT_TRUE(std::isnan(record.stages().search.max_ms));
}

}  // namespace
}  // namespace ifar::runner
