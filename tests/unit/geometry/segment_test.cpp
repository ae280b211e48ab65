#include "common/geometry/segment.hpp"

#include <gtest/gtest.h>

namespace ifar::geometry {
namespace {

Segment segment(double x0, double y0, double x1, double y1)
{
  return Segment{Point(x0, y0), Point(x1, y1)};
}

TEST(Segment, ProperCrossing)
{
  const Segment first = segment(0, 0, 2, 2);
  const Segment second = segment(0, 2, 2, 0);
  EXPECT_TRUE(segmentsIntersect(first, second));
  EXPECT_TRUE(segmentsCrossProperly(first, second));
  const auto point = segmentIntersectionPoint(first, second);
  ASSERT_TRUE(point.has_value());
  EXPECT_DOUBLE_EQ(point->x(), 1.0);
  EXPECT_DOUBLE_EQ(point->y(), 1.0);
}

TEST(Segment, CollinearOverlap)
{
  const Segment first = segment(0, 0, 2, 0);
  const Segment second = segment(1, 0, 3, 0);
  EXPECT_TRUE(segmentsIntersect(first, second));
  EXPECT_FALSE(segmentsCrossProperly(first, second));
  EXPECT_FALSE(segmentIntersectionPoint(first, second).has_value());
  // One containing the other.
  EXPECT_TRUE(segmentsIntersect(segment(0, 0, 4, 4), segment(1, 1, 2, 2)));
  EXPECT_FALSE(segmentIntersectionPoint(segment(0, 0, 4, 4), segment(1, 1, 2, 2)).has_value());
}

TEST(Segment, CollinearDisjoint)
{
  const Segment first = segment(0, 0, 1, 0);
  const Segment second = segment(2, 0, 3, 0);
  EXPECT_FALSE(segmentsIntersect(first, second));
  EXPECT_FALSE(segmentsCrossProperly(first, second));
  EXPECT_FALSE(segmentIntersectionPoint(first, second).has_value());
}

TEST(Segment, CollinearTouchingEndToEnd)
{
  const Segment first = segment(0, 0, 1, 1);
  const Segment second = segment(1, 1, 3, 3);
  EXPECT_TRUE(segmentsIntersect(first, second));
  EXPECT_FALSE(segmentsCrossProperly(first, second));
  const auto point = segmentIntersectionPoint(first, second);
  ASSERT_TRUE(point.has_value());
  EXPECT_NEAR(point->x(), 1.0, 1e-12);
  EXPECT_NEAR(point->y(), 1.0, 1e-12);
}

TEST(Segment, TouchingEndPointsAtAnAngle)
{
  const Segment first = segment(0, 0, 1, 0);
  const Segment second = segment(1, 0, 1, 5);
  EXPECT_TRUE(segmentsIntersect(first, second));
  EXPECT_FALSE(segmentsCrossProperly(first, second));
  const auto point = segmentIntersectionPoint(first, second);
  ASSERT_TRUE(point.has_value());
  EXPECT_DOUBLE_EQ(point->x(), 1.0);
  EXPECT_DOUBLE_EQ(point->y(), 0.0);
}

TEST(Segment, TTouch)
{
  const Segment bar = segment(-1, 0, 1, 0);
  const Segment stem = segment(0, 0, 0, -2);
  EXPECT_TRUE(segmentsIntersect(bar, stem));
  EXPECT_TRUE(segmentsIntersect(stem, bar));
  EXPECT_FALSE(segmentsCrossProperly(bar, stem));
  EXPECT_FALSE(segmentsCrossProperly(stem, bar));
  const auto point = segmentIntersectionPoint(bar, stem);
  ASSERT_TRUE(point.has_value());
  EXPECT_DOUBLE_EQ(point->x(), 0.0);
  EXPECT_DOUBLE_EQ(point->y(), 0.0);
}

TEST(Segment, StemStoppingShortOfTheBar)
{
  EXPECT_FALSE(segmentsIntersect(segment(-1, 0, 1, 0), segment(0, -0.001, 0, -2)));
  // Crossing the supporting line but beyond the bar's end.
  EXPECT_FALSE(segmentsIntersect(segment(-1, 0, 1, 0), segment(1.5, 1, 1.5, -1)));
}

TEST(Segment, ZeroLengthOnAndOffSegment)
{
  const Segment line = segment(0, 0, 4, 2);
  const Segment on = segment(2, 1, 2, 1);
  const Segment off = segment(2, 1.5, 2, 1.5);
  EXPECT_TRUE(segmentsIntersect(line, on));
  EXPECT_TRUE(segmentsIntersect(on, line));
  EXPECT_FALSE(segmentsCrossProperly(line, on));
  const auto point = segmentIntersectionPoint(on, line);
  ASSERT_TRUE(point.has_value());
  EXPECT_DOUBLE_EQ(point->x(), 2.0);
  EXPECT_DOUBLE_EQ(point->y(), 1.0);
  EXPECT_FALSE(segmentsIntersect(line, off));
  EXPECT_FALSE(segmentIntersectionPoint(line, off).has_value());
  // Zero-length on the supporting line but outside the segment.
  EXPECT_FALSE(segmentsIntersect(line, segment(6, 3, 6, 3)));
}

TEST(Segment, TwoZeroLengthSegments)
{
  EXPECT_TRUE(segmentsIntersect(segment(1, 1, 1, 1), segment(1, 1, 1, 1)));
  EXPECT_FALSE(segmentsIntersect(segment(1, 1, 1, 1), segment(1, 2, 1, 2)));
  EXPECT_FALSE(segmentsCrossProperly(segment(1, 1, 1, 1), segment(1, 1, 1, 1)));
}

TEST(Segment, Parallel)
{
  const Segment first = segment(0, 0, 2, 0);
  const Segment second = segment(0, 1, 2, 1);
  EXPECT_FALSE(segmentsIntersect(first, second));
  EXPECT_FALSE(segmentsCrossProperly(first, second));
  EXPECT_FALSE(segmentIntersectionPoint(first, second).has_value());
}

TEST(Segment, DistanceAndClosestPoint)
{
  const Segment line = segment(0, 0, 4, 0);
  EXPECT_DOUBLE_EQ(distanceToSegment(Point(2, 3), line), 3.0);
  EXPECT_DOUBLE_EQ(distanceToSegment(Point(-3, 4), line), 5.0);  // beyond the start: to the end point
  EXPECT_DOUBLE_EQ(distanceToSegment(Point(7, -4), line), 5.0);
  EXPECT_DOUBLE_EQ(distanceToSegment(Point(1, 0), line), 0.0);
  const Point closest = closestPointOnSegment(Point(2.5, -1), line);
  EXPECT_DOUBLE_EQ(closest.x(), 2.5);
  EXPECT_DOUBLE_EQ(closest.y(), 0.0);
  EXPECT_DOUBLE_EQ(distanceToSegment(Point(4, 5), segment(1, 1, 1, 1)), 5.0);
  EXPECT_DOUBLE_EQ(segment(0, 0, 3, 4).length(), 5.0);
}

}  // namespace
}  // namespace ifar::geometry
