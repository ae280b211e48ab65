#include "planner/perception/classification.hpp"

#include <gtest/gtest.h>

namespace ifar::perception {
namespace {

WorldPoint pointAt(double x, double y, float reflectivity)
{
  WorldPoint point;
  point.position_world = Eigen::Vector3d(x, y, 0.5);
  point.reflectivity = reflectivity;
  return point;
}

TEST(Classification, ByReflectivityThreshold)
{
  const std::vector<WorldPoint> points = {pointAt(1, 0, 20.0F), pointAt(2, 0, 100.0F), pointAt(3, 0, 101.0F),
                                          pointAt(4, 0, 255.0F)};
  const ClassifiedPoints result = classifyByReflectivity(points, 101.0F);
  ASSERT_EQ(result.background.size(), 2U);
  ASSERT_EQ(result.movable.size(), 2U);
  EXPECT_EQ(result.background[0], geometry::Point(1, 0));
  EXPECT_EQ(result.background[1], geometry::Point(2, 0));
  EXPECT_EQ(result.movable[0], geometry::Point(3, 0));  // the threshold itself is movable
  EXPECT_EQ(result.movable[1], geometry::Point(4, 0));
}

TEST(Classification, ByDetectorPolygonsIgnoresReflectivity)
{
  const std::vector<geometry::Polygon> detected = {
      {geometry::Point(0, 0), geometry::Point(2, 0), geometry::Point(2, 2), geometry::Point(0, 2)},
      {geometry::Point(5, 5), geometry::Point(6, 5), geometry::Point(5.5, 6)}};
  const std::vector<WorldPoint> points = {
      pointAt(1, 1, 10.0F),     // inside, dull: movable
      pointAt(2, 1, 10.0F),     // on the edge: movable
      pointAt(3, 1, 250.0F),    // outside, bright: background
      pointAt(5.5, 5.2, 0.0F),  // inside the triangle
      pointAt(5.9, 5.9, 0.0F),  // in the triangle's bounding box, outside the triangle
  };
  const ClassifiedPoints result = classifyByDetector(points, detected);
  ASSERT_EQ(result.movable.size(), 3U);
  ASSERT_EQ(result.background.size(), 2U);
  EXPECT_EQ(result.movable[0], geometry::Point(1, 1));
  EXPECT_EQ(result.movable[1], geometry::Point(2, 1));
  EXPECT_EQ(result.movable[2], geometry::Point(5.5, 5.2));
  EXPECT_EQ(result.background[0], geometry::Point(3, 1));
  EXPECT_EQ(result.background[1], geometry::Point(5.9, 5.9));
}

TEST(Classification, NoDetectedObjectsMeansAllBackground)
{
  const std::vector<WorldPoint> points = {pointAt(1, 1, 250.0F), pointAt(2, 2, 10.0F)};
  const ClassifiedPoints result = classifyByDetector(points, {});
  EXPECT_TRUE(result.movable.empty());
  EXPECT_EQ(result.background.size(), 2U);
}

}  // namespace
}  // namespace ifar::perception
