#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/percentile.hpp"

TEST(Percentile, NearestRank)
{
  using ifar::common::nearestRankPercentile;
  const std::vector<double> values{5.0, 1.0, 4.0, 2.0, 3.0};
  EXPECT_EQ(nearestRankPercentile(values, 50.0), 3.0);
  EXPECT_EQ(nearestRankPercentile(values, 99.0), 5.0);
  EXPECT_EQ(nearestRankPercentile(values, 0.0), 1.0);
  EXPECT_EQ(nearestRankPercentile({7.0, 1.0}, 50.0), 1.0);  // rank ceil(1.0) = 1: the lower of two
  EXPECT_TRUE(std::isnan(nearestRankPercentile({}, 50.0)));
}
