#include "system/saturated_push_watch.hpp"

#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace ifar::runner {
namespace {

constexpr double kSaturatedN = 500.0;
constexpr double kLimitS = 4.0;
constexpr std::int64_t kStepUs = 10'000;

/// Feeds `force_n` every 10 ms from `from_us` for `seconds`; returns the time after the last sample.
std::int64_t hold(SaturatedPushWatch& watch, std::int64_t from_us, double seconds, double force_n)
{
  std::int64_t now_us = from_us;
  for (int step = 0; step < static_cast<int>(seconds * 100.0); ++step) {
    watch.force(now_us, force_n);
    now_us += kStepUs;
  }
  return now_us;
}

TEST(SaturatedPushWatch, APushAtMaximumBeyondTheLimitCountsOnce)
{
  SaturatedPushWatch watch(kSaturatedN, kLimitS);
  hold(watch, 0, 10.0, 600.0);
  EXPECT_EQ(watch.undecided(), 1);
  EXPECT_NEAR(watch.longestUndecidedSeconds(), 9.99, 1e-9);
}

TEST(SaturatedPushWatch, ShorterSpellsAndForcesBelowMaximumDoNotCount)
{
  SaturatedPushWatch watch(kSaturatedN, kLimitS);
  std::int64_t now_us = hold(watch, 0, 3.9, 600.0);
  now_us = hold(watch, now_us, 0.1, 100.0);  // the force drops: the spell ends
  now_us = hold(watch, now_us, 3.9, 600.0);
  hold(watch, now_us, 20.0, 499.0);
  EXPECT_EQ(watch.undecided(), 0);
  EXPECT_LT(watch.longestUndecidedSeconds(), kLimitS);
}

TEST(SaturatedPushWatch, ADecisionWithinTheLimitRestartsTheSpell)
{
  SaturatedPushWatch watch(kSaturatedN, kLimitS);
  std::int64_t now_us = hold(watch, 0, 3.0, 600.0);
  watch.decided(now_us);
  now_us = hold(watch, now_us, 3.0, 600.0);
  EXPECT_EQ(watch.undecided(), 0);
  // Still at maximum long after the decision: the decision changed nothing, and that counts.
  hold(watch, now_us, 2.0, 600.0);
  EXPECT_EQ(watch.undecided(), 1);
}

TEST(SaturatedPushWatch, NotANumberIsNotAForceAtMaximum)
{
  SaturatedPushWatch watch(kSaturatedN, kLimitS);
  hold(watch, 0, 10.0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(watch.undecided(), 0);
}

}  // namespace
}  // namespace ifar::runner
