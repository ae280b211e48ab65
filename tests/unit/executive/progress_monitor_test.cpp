#include "executive/modes/progress_monitor.hpp"

#include <cstdint>

#include <gtest/gtest.h>

namespace ifar::executive {
namespace {

using geometry::Point;

constexpr std::int64_t kSecondUs = 1'000'000;

ProgressSettings tenSeconds()
{
  ProgressSettings settings;
  settings.timeout_s = 10.0;
  settings.margin_m = 0.5;
  settings.new_ground_m = 2.0;
  return settings;
}

/// Seconds of 10 Hz updates at `position` with `remaining_m` until the first escalation (-1: none in
/// `limit_s`), starting at `start_us`.
double secondsToEscalation(ProgressMonitor& monitor, std::int64_t& now_us, const Point& position,
                           double remaining_m, double limit_s, bool counting = true)
{
  for (int tick = 1; tick <= static_cast<int>(limit_s * 10.0); ++tick) {
    now_us += kSecondUs / 10;
    if (monitor.update(now_us, position, remaining_m, counting)) {
      return tick / 10.0;
    }
  }
  return -1.0;
}

TEST(ProgressMonitor, NoProgressForTheTimeoutEscalatesOnceThenStartsAgain)
{
  ProgressMonitor monitor(tenSeconds());
  std::int64_t now_us = 0;
  EXPECT_FALSE(monitor.update(now_us, Point(0.0, 0.0), 20.0, true));
  EXPECT_NEAR(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 20.0, 30.0), 10.0, 0.11);
  // The clock starts again: a second escalation after another timeout, not at once.
  EXPECT_NEAR(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 20.0, 30.0), 10.0, 0.11);
}

TEST(ProgressMonitor, ProgressResetsTheClock)
{
  ProgressMonitor monitor(tenSeconds());
  std::int64_t now_us = 0;
  monitor.update(now_us, Point(0.0, 0.0), 20.0, true);
  EXPECT_LT(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 20.0, 8.0), 0.0);
  // 0.6 m shorter (beyond the 0.5 m margin): progress, a fresh 10 s.
  EXPECT_FALSE(monitor.update(now_us, Point(0.0, 0.0), 19.4, true));
  EXPECT_DOUBLE_EQ(monitor.stuckSeconds(), 0.0);
  EXPECT_LT(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 19.4, 9.0), 0.0);
  EXPECT_GT(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 19.4, 5.0), 0.0);
}

TEST(ProgressMonitor, ShorteningWithinTheMarginIsNoProgress)
{
  ProgressMonitor monitor(tenSeconds());
  std::int64_t now_us = 0;
  monitor.update(now_us, Point(0.0, 0.0), 20.0, true);
  // Dithering: 0.3 m shorter, then longer again, in the same square.
  EXPECT_LT(secondsToEscalation(monitor, now_us, Point(0.1, 0.0), 19.7, 5.0), 0.0);
  EXPECT_NEAR(secondsToEscalation(monitor, now_us, Point(0.2, 0.0), 20.3, 10.0), 5.0, 0.11);
}

TEST(ProgressMonitor, ALoopBetweenTwoRoutesEscalatesButNewGroundDoesNot)
{
  // The path flips between a 20 m and a 25 m route while the vehicle circles in two squares it has seen:
  // the best remaining length is never beaten.
  ProgressMonitor monitor(tenSeconds());
  std::int64_t now_us = 0;
  monitor.update(now_us, Point(0.5, 0.5), 20.0, true);
  monitor.update(now_us, Point(2.5, 0.5), 25.0, true);
  bool escalated = false;
  for (int tick = 0; tick < 200 && !escalated; ++tick) {
    now_us += kSecondUs / 10;
    const bool east = (tick / 20) % 2 == 0;
    escalated = monitor.update(now_us, Point(east ? 2.5 : 0.5, 0.5), east ? 25.0 : 20.5, true);
  }
  EXPECT_TRUE(escalated);
  // Driving on round an obstacle first seen on the way (the path grows) reaches new squares: progress.
  ProgressMonitor exploring(tenSeconds());
  now_us = 0;
  exploring.update(now_us, Point(0.0, 0.0), 20.0, true);
  for (int tick = 0; tick < 300; ++tick) {
    now_us += kSecondUs / 10;
    ASSERT_FALSE(exploring.update(now_us, Point(0.05 * tick, 0.0), 30.0, true)) << "tick " << tick;
  }
}

TEST(ProgressMonitor, TimeNotCountingDoesNotEscalateAndZeroTimeoutIsOff)
{
  ProgressMonitor monitor(tenSeconds());
  std::int64_t now_us = 0;
  monitor.update(now_us, Point(0.0, 0.0), 20.0, true);
  // Waiting for a replan or stopped for a stale input: not the loop getting nowhere.
  EXPECT_LT(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 20.0, 60.0, false), 0.0);
  EXPECT_NEAR(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 20.0, 30.0), 10.0, 0.11);

  ProgressSettings off = tenSeconds();
  off.timeout_s = 0.0;
  ProgressMonitor never(off);
  now_us = 0;
  never.update(now_us, Point(0.0, 0.0), 20.0, true);
  EXPECT_LT(secondsToEscalation(never, now_us, Point(0.0, 0.0), 20.0, 600.0), 0.0);
}

TEST(ProgressMonitor, ANewGoalForgetsTheBest)
{
  ProgressMonitor monitor(tenSeconds());
  std::int64_t now_us = 0;
  monitor.update(now_us, Point(0.0, 0.0), 5.0, true);
  EXPECT_LT(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 30.0, 8.0), 0.0);
  monitor.startGoal();
  EXPECT_FALSE(monitor.bestRemaining().has_value());
  monitor.update(now_us, Point(0.0, 0.0), 30.0, true);
  EXPECT_DOUBLE_EQ(*monitor.bestRemaining(), 30.0);
  EXPECT_NEAR(secondsToEscalation(monitor, now_us, Point(0.0, 0.0), 30.0, 30.0), 10.0, 0.11);
}

}  // namespace
}  // namespace ifar::executive
