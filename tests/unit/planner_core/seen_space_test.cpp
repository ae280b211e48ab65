#include "planner/core/seen_space.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ifar::planner {
namespace {

using geometry::Point;

/// A layer centred on the origin whose background is a thin wall along x = 2 (points from y = -3 to 3),
/// inflated by the default 0.35 m.
perception::LocalLayer wallLayer()
{
  perception::PerceptionSettings settings;
  settings.layer_size_m = 20.0;
  perception::ClassifiedPoints points;
  for (double y = -3.0; y <= 3.0; y += 0.05) {
    points.background.emplace_back(2.0, y);
  }
  return perception::buildLocalLayer(points, Point(0.0, 0.0), settings);
}

TEST(SeenSpace, ScansSeeUpToTheFirstObstacleAndTheRange)
{
  const perception::LocalLayer layer = wallLayer();
  SeenSpace seen;
  EXPECT_FALSE(seen.seen(Point(1.0, 0.0)));
  EXPECT_DOUBLE_EQ(seen.unseenLength(Point(0.0, 0.0), Point(5.0, 0.0)), 5.0);

  seen.markView(layer, Point(0.0, 0.0), 6.0, 0.35);
  EXPECT_TRUE(seen.seen(Point(1.0, 0.0)));
  EXPECT_FALSE(seen.seen(Point(4.0, 0.0)));  // behind the wall
  EXPECT_FALSE(seen.seen(Point(4.0, 2.5)));
  EXPECT_TRUE(seen.seen(Point(2.0, 5.0)));     // past the wall's end, 5.4 m away
  EXPECT_TRUE(seen.seen(Point(-5.0, 0.0)));    // beyond the raster (no return) but within the range
  EXPECT_FALSE(seen.seen(Point(-7.0, 0.0)));   // beyond the range
  EXPECT_FALSE(seen.seen(Point(40.0, 40.0)));  // beyond the grid

  // Seen up to the cell where the ray met the inflated wall (x 1.5-2.0), unseen from there on.
  EXPECT_NEAR(seen.unseenLength(Point(0.0, 0.0), Point(5.0, 0.0)), 3.0, 1e-9);
  EXPECT_NEAR(seen.unseenLength(Point(5.0, 0.0), Point(0.0, 0.0)), 3.0, 1e-9);
  // Across the wall at a slant: the part east of x = 2 (3 of its 5 m along x) is unseen.
  EXPECT_NEAR(seen.unseenLength(Point(0.0, -1.0), Point(5.0, 1.0)), 0.6 * std::hypot(5.0, 2.0), 1e-9);
  EXPECT_DOUBLE_EQ(seen.unseenLength(Point(-1.0, 1.0), Point(-1.0, -1.0)), 0.0);
  EXPECT_DOUBLE_EQ(seen.unseenLength(Point(1.0, 1.0), Point(1.0, 1.0)), 0.0);

  // A second view from the other side of the wall adds to the first; the grid grows to hold it.
  seen.markView(layer, Point(30.0, 0.0), 6.0, 0.35);
  EXPECT_TRUE(seen.seen(Point(1.0, 0.0)));
  EXPECT_TRUE(seen.seen(Point(26.0, 0.0)));
  EXPECT_FALSE(seen.seen(Point(20.0, 0.0)));
}

TEST(SeenSpace, AViewpointInsideTheInflationSeesOutButNotThroughTheWall)
{
  const perception::LocalLayer layer = wallLayer();
  SeenSpace seen;
  // 0.2 m from the wall, inside its 0.35 m inflation.
  seen.markView(layer, Point(1.8, 0.0), 6.0, 0.35);
  EXPECT_TRUE(seen.seen(Point(0.0, 0.0)));
  EXPECT_TRUE(seen.seen(Point(-3.0, 1.0)));
  EXPECT_FALSE(seen.seen(Point(3.5, 0.0)));

  // With no inflation to pass, the rays stop where they start.
  SeenSpace stopped;
  stopped.markView(layer, Point(1.8, 0.0), 6.0, 0.0);
  EXPECT_FALSE(stopped.seen(Point(0.0, 0.0)));
}

TEST(SeenSpace, AViewKilometresAwayStartsTheGridAfresh)
{
  const perception::LocalLayer layer = wallLayer();
  SeenSpace seen;
  seen.markView(layer, Point(0.0, 0.0), 6.0, 0.35);
  const std::size_t first = seen.seenCells();
  EXPECT_GT(first, 100U);
  seen.markView(layer, Point(5000.0, 5000.0), 6.0, 0.35);
  EXPECT_TRUE(seen.seen(Point(5001.0, 5000.0)));
  EXPECT_FALSE(seen.seen(Point(-1.0, 0.0))) << "forgotten rather than a grid of 5 km x 5 km";
  EXPECT_LT(seen.seenCells(), 2 * first);
}

TEST(SeenSpace, BadViewsMarkNothing)
{
  const perception::LocalLayer layer = wallLayer();
  SeenSpace seen;
  seen.markView(layer, Point(std::numeric_limits<double>::quiet_NaN(), 0.0), 6.0, 0.35);
  seen.markView(layer, Point(0.0, 0.0), 0.0, 0.35);
  EXPECT_EQ(seen.seenCells(), 0U);
  EXPECT_FALSE(seen.seen(Point(0.0, 0.0)));
}

}  // namespace
}  // namespace ifar::planner
