#include "planner/perception/line_of_sight.hpp"

#include <gtest/gtest.h>

namespace ifar::perception {
namespace {

/// A layer whose background is a wall along x = 2 (real points from y = -3 to 3), inflated by 0.35 m.
LocalLayer wallLayer()
{
  PerceptionSettings settings;
  settings.layer_size_m = 20.0;
  ClassifiedPoints points;
  for (double y = -3.0; y <= 3.0; y += 0.05) {
    points.background.emplace_back(2.0, y);
  }
  return buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
}

TEST(LineOfSight, AWallBetweenBlocksAndAWallBesideDoesNot)
{
  const LocalLayer layer = wallLayer();
  EXPECT_FALSE(backgroundClearAlong(layer, geometry::Point(0.0, 0.0), geometry::Point(4.0, 0.0), 0.5));
  EXPECT_TRUE(backgroundClearAlong(layer, geometry::Point(0.0, 0.0), geometry::Point(0.0, 4.0), 0.5));
  // Round the wall's end (y > 3 + inflation).
  EXPECT_TRUE(backgroundClearAlong(layer, geometry::Point(0.0, 4.0), geometry::Point(4.0, 4.0), 0.5));
  // An object leaning on the wall (centre 0.25 m off it) is in sight: the ends are skipped.
  EXPECT_TRUE(backgroundClearAlong(layer, geometry::Point(-2.0, 0.0), geometry::Point(1.75, 0.0), 0.5));
  EXPECT_FALSE(backgroundClearAlong(layer, geometry::Point(-2.0, 0.0), geometry::Point(1.75, 0.0), 0.0));
  // Beyond the raster nothing is known, so nothing blocks.
  EXPECT_TRUE(backgroundClearAlong(layer, geometry::Point(0.0, 0.0), geometry::Point(-9.0, 0.0), 0.5));
}

}  // namespace
}  // namespace ifar::perception
