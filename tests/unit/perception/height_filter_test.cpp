#include "planner/perception/height_filter.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace ifar::perception {
namespace {

WorldPoint pointAt(double x, double height, double range)
{
  WorldPoint point;
  point.position_world = Eigen::Vector3d(x, 0.0, height);
  point.height_above_ground_m = height;
  point.range_m = range;
  return point;
}

TEST(HeightFilter, KeepsTheBandBetweenClearanceAndVehicleHeight)
{
  PerceptionSettings settings;
  settings.ground_clearance_m = 0.15;
  settings.vehicle_height_m = 1.2;
  settings.min_range_m = 0.4;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  WorldPoint nan_height = pointAt(1.0, 0.5, 2.0);
  nan_height.height_above_ground_m = nan;
  const std::vector<WorldPoint> points = {
      pointAt(1.0, 0.10, 2.0),      // ground
      pointAt(2.0, 0.15, 2.0),      // at the clearance: kept
      pointAt(3.0, 0.60, 2.0),      // kept
      pointAt(4.0, 1.20, 2.0),      // at the vehicle height: kept
      pointAt(5.0, 1.30, 2.0),      // overhang
      pointAt(6.0, 0.60, 0.3),      // too close to the sensor
      pointAt(nan, 0.60, 2.0),      // malformed
      pointAt(infinity, 0.6, 2.0),  // malformed
      nan_height,                   // malformed
  };
  const HeightFilterResult result = filterObstaclePoints(points, settings);
  ASSERT_EQ(result.obstacle_points.size(), 3U);
  EXPECT_EQ(result.obstacle_points[0].position_world.x(), 2.0);
  EXPECT_EQ(result.obstacle_points[1].position_world.x(), 3.0);
  EXPECT_EQ(result.obstacle_points[2].position_world.x(), 4.0);
  EXPECT_EQ(result.counts.kept, 3U);
  EXPECT_EQ(result.counts.non_finite, 3U);
  EXPECT_EQ(result.counts.too_close, 1U);
  EXPECT_EQ(result.counts.outside_height_band, 2U);
}

TEST(HeightFilter, EmptyInput)
{
  const HeightFilterResult result = filterObstaclePoints({}, PerceptionSettings{});
  EXPECT_TRUE(result.obstacle_points.empty());
  EXPECT_EQ(result.counts.non_finite, 0U);
  EXPECT_EQ(result.counts.kept, 0U);
}

}  // namespace
}  // namespace ifar::perception
