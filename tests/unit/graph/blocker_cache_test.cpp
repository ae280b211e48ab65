// The visibility caches are pure accelerators: a test through BlockerCache or SectorBlockerCache must
// answer exactly what the plain test answers, whatever order lines are tested in and whatever the caches
// remember from earlier lines.

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "planner/graph/obstacle_set.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;

/// A field of axis-aligned and rotated boxes, seeded: many blockers in every direction.
ObstacleSet clutteredField(unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> centre(0.0, 100.0);
  std::uniform_real_distribution<double> size(0.5, 6.0);
  std::uniform_real_distribution<double> angle(0.0, 3.14159);
  std::vector<ObstacleLoop> loops;
  for (int box = 0; box < 150; ++box) {
    const Point middle(centre(random), centre(random));
    const double half_width = 0.5 * size(random);
    const double half_height = 0.5 * size(random);
    const double heading = angle(random);
    const Point along(std::cos(heading), std::sin(heading));
    const Point across(-along.y(), along.x());
    loops.push_back(loopFromPolygon({middle - along * half_width - across * half_height,
                                     middle + along * half_width - across * half_height,
                                     middle + along * half_width + across * half_height,
                                     middle - along * half_width + across * half_height}));
  }
  return ObstacleSet(std::move(loops));
}

std::vector<Point> randomPoints(unsigned seed, int count)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-5.0, 105.0);
  std::vector<Point> points;
  for (int index = 0; index < count; ++index) {
    points.emplace_back(coordinate(random), coordinate(random));
  }
  return points;
}

TEST(BlockerCache, SectorCacheAnswersExactlyAsThePlainTest)
{
  const ObstacleSet obstacles = clutteredField(7);
  const std::vector<Point> origins = randomPoints(11, 20);
  const std::vector<Point> targets = randomPoints(13, 2000);
  std::size_t blocked = 0;
  std::size_t free = 0;
  for (const Point& origin : origins) {
    SectorBlockerCache cache(origin);
    for (const Point& target : targets) {
      const bool expected = obstacles.visible(origin, target);
      ASSERT_EQ(obstacles.visibleFrom(target, cache), expected)
          << "from (" << origin.x() << ", " << origin.y() << ") to (" << target.x() << ", " << target.y()
          << ")";
      (expected ? free : blocked) += 1;
    }
  }
  // Both answers occur often, so a cache that always said one thing would fail above.
  EXPECT_GT(blocked, 5000U);
  EXPECT_GT(free, 1000U);
}

TEST(BlockerCache, RecentBlockerCacheAnswersExactlyAsThePlainTest)
{
  const ObstacleSet obstacles = clutteredField(21);
  const std::vector<Point> starts = randomPoints(23, 3000);
  const std::vector<Point> ends = randomPoints(29, 3000);
  BlockerCache cache;  // shared across unrelated lines: stale entries must not change answers
  for (std::size_t index = 0; index < starts.size(); ++index) {
    ASSERT_EQ(obstacles.visible(starts[index], ends[index], cache),
              obstacles.visible(starts[index], ends[index]))
        << "line " << index;
  }
}

}  // namespace
}  // namespace ifar::graph
