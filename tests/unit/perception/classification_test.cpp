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
  TagReading own;
  own.threshold = 101.0F;
  const ClassifiedPoints result = classifyByReflectivity(points, own);
  ASSERT_EQ(result.background.size(), 2U);
  ASSERT_EQ(result.movable.size(), 2U);
  EXPECT_EQ(result.background[0], geometry::Point(1, 0));
  EXPECT_EQ(result.background[1], geometry::Point(2, 0));
  EXPECT_EQ(result.movable[0], geometry::Point(3, 0));  // the threshold itself is movable
  EXPECT_EQ(result.movable[1], geometry::Point(4, 0));
}

// A face of a tagged object with one missed return, a wall with one false tag, and an object standing
// against the wall: the lone dissenters take their neighbourhood's class, the touching faces keep theirs.
TEST(Classification, NeighbourhoodOverrulesLoneTagErrors)
{
  std::vector<WorldPoint> points;
  for (int step = 0; step < 10; ++step) {
    const double along = 0.02 * step;
    points.push_back(pointAt(1.0, 1.0 + along, step == 4 ? 30.0F : 200.0F));  // object face, one missed
    points.push_back(pointAt(5.0 + along, 1.0, step == 6 ? 180.0F : 20.0F));  // wall, one false tag
  }
  for (int step = 0; step < 6; ++step) {  // object against the wall: 6 tagged and 6 untagged side by side
    points.push_back(pointAt(9.0 + 0.02 * step, 1.05, 200.0F));
    points.push_back(pointAt(9.0 + 0.02 * step, 0.95, 20.0F));
  }
  TagReading reading;
  reading.threshold = 101.0F;
  reading.neighbourhood_m = 0.15;
  const ClassifiedPoints voted = classifyByReflectivity(points, reading);
  std::size_t object_movable = 0;
  std::size_t wall_background = 0;
  for (const geometry::Point& point : voted.movable) {
    object_movable += point.x() < 2.0 ? 1U : 0U;
  }
  for (const geometry::Point& point : voted.background) {
    wall_background += point.x() > 4.0 && point.x() < 6.0 ? 1U : 0U;
  }
  EXPECT_EQ(object_movable, 10U);
  EXPECT_EQ(wall_background, 10U);
  EXPECT_EQ(voted.movable.size(), 16U);  // 10 on the object face, 6 on the object against the wall
  EXPECT_EQ(voted.background.size(), 16U);

  TagReading own = reading;
  own.neighbourhood_m = 0.0;
  const ClassifiedPoints unvoted = classifyByReflectivity(points, own);
  EXPECT_EQ(unvoted.movable.size(), 16U);  // 9 + 1 false tag + 6
  EXPECT_EQ(unvoted.background.size(), 16U);
  std::size_t unvoted_object_movable = 0;
  for (const geometry::Point& point : unvoted.movable) {
    unvoted_object_movable += point.x() < 2.0 ? 1U : 0U;
  }
  EXPECT_EQ(unvoted_object_movable, 9U);
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
