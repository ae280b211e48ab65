#include <gtest/gtest.h>

#include "common/rate_limiter.hpp"

TEST(RateLimiter, AllowsOncePerIntervalAndCountsTheRest)
{
  ifar::common::RateLimiter limiter(1000);
  EXPECT_TRUE(limiter.allow(5000));
  EXPECT_FALSE(limiter.allow(5500));
  EXPECT_FALSE(limiter.allow(5999));
  EXPECT_TRUE(limiter.allow(6000));
  EXPECT_EQ(limiter.takeSuppressed(), 2);
  EXPECT_EQ(limiter.takeSuppressed(), 0);
}
