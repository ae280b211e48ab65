#include "common/geometry/polygon.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"
#include "common/geometry/pose2.hpp"

namespace ifar::geometry {
namespace {

Polygon rectangle(double x0, double y0, double x1, double y1)
{
  return {Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)};
}

/// An L shape (concave at (1, 1)).
Polygon lShape()
{
  return {Point(0, 0), Point(2, 0), Point(2, 1), Point(1, 1), Point(1, 2), Point(0, 2)};
}

TEST(PolygonArea, SignFollowsOrientation)
{
  const Polygon square = rectangle(0, 0, 2, 3);
  EXPECT_DOUBLE_EQ(signedArea(square), 6.0);
  const Polygon clockwise(square.rbegin(), square.rend());
  EXPECT_DOUBLE_EQ(signedArea(clockwise), -6.0);
  EXPECT_DOUBLE_EQ(area(clockwise), 6.0);
  EXPECT_DOUBLE_EQ(signedArea(lShape()), 3.0);
  EXPECT_DOUBLE_EQ(signedArea({Point(0, 0), Point(1, 1)}), 0.0);
  EXPECT_DOUBLE_EQ(signedArea({}), 0.0);
  EXPECT_DOUBLE_EQ(signedArea({Point(0, 0), Point(1, 1), Point(2, 2)}), 0.0);
}

TEST(PolygonArea, CounterClockwiseReversesOnlyClockwise)
{
  const Polygon square = rectangle(0, 0, 1, 1);
  EXPECT_EQ(counterClockwise(square), square);
  const Polygon clockwise(square.rbegin(), square.rend());
  const Polygon fixed = counterClockwise(clockwise);
  EXPECT_DOUBLE_EQ(signedArea(fixed), 1.0);
}

TEST(PolygonMeasures, CentroidPerimeterEdge)
{
  const Point centre = centroid(rectangle(1, 1, 3, 5));
  EXPECT_DOUBLE_EQ(centre.x(), 2.0);
  EXPECT_DOUBLE_EQ(centre.y(), 3.0);
  const Point l_centre = centroid(lShape());
  EXPECT_NEAR(l_centre.x(), 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(l_centre.y(), 5.0 / 6.0, 1e-12);
  EXPECT_DOUBLE_EQ(perimeter(rectangle(0, 0, 2, 5)), 14.0);
  const Segment last = polygonEdge(rectangle(0, 0, 2, 5), 3);
  EXPECT_EQ(last.start, Point(0, 5));
  EXPECT_EQ(last.end, Point(0, 0));
}

TEST(PointInPolygon, InsideOutsideEdgeVertex)
{
  const Polygon square = rectangle(0, 0, 2, 2);
  EXPECT_EQ(locatePoint(square, Point(1, 1)), Containment::Inside);
  EXPECT_EQ(locatePoint(square, Point(3, 1)), Containment::Outside);
  EXPECT_EQ(locatePoint(square, Point(-0.5, 1)), Containment::Outside);
  EXPECT_EQ(locatePoint(square, Point(2, 1)), Containment::Boundary);
  EXPECT_EQ(locatePoint(square, Point(1, 0)), Containment::Boundary);
  EXPECT_EQ(locatePoint(square, Point(2, 2)), Containment::Boundary);
  EXPECT_EQ(locatePoint(square, Point(0, 0)), Containment::Boundary);
  EXPECT_TRUE(containsPoint(square, Point(0, 0)));
  EXPECT_FALSE(containsPoint(square, Point(2.001, 1)));
  // A ray through a vertex must count once: the point level with the top corner, to its left.
  const Polygon diamond = {Point(0, -1), Point(1, 0), Point(0, 1), Point(-1, 0)};
  EXPECT_EQ(locatePoint(diamond, Point(-2, 0)), Containment::Outside);
  EXPECT_EQ(locatePoint(diamond, Point(0, 0)), Containment::Inside);
  EXPECT_EQ(locatePoint(diamond, Point(0.5, 0.5)), Containment::Boundary);
}

TEST(PointInPolygon, ConcavePolygon)
{
  const Polygon shape = lShape();
  EXPECT_EQ(locatePoint(shape, Point(0.5, 1.5)), Containment::Inside);
  EXPECT_EQ(locatePoint(shape, Point(1.5, 0.5)), Containment::Inside);
  EXPECT_EQ(locatePoint(shape, Point(1.5, 1.5)), Containment::Outside);  // the notch
  EXPECT_EQ(locatePoint(shape, Point(1, 1)), Containment::Boundary);     // the reflex vertex
  EXPECT_EQ(locatePoint(shape, Point(1.5, 1)), Containment::Boundary);
  // Clockwise input gives the same answers.
  const Polygon clockwise(shape.rbegin(), shape.rend());
  EXPECT_EQ(locatePoint(clockwise, Point(1.5, 1.5)), Containment::Outside);
  EXPECT_EQ(locatePoint(clockwise, Point(0.5, 0.5)), Containment::Inside);
}

TEST(PointInPolygon, DegeneratePolygons)
{
  EXPECT_EQ(locatePoint({}, Point(0, 0)), Containment::Outside);
  EXPECT_EQ(locatePoint({Point(1, 1)}, Point(1, 1)), Containment::Boundary);
  EXPECT_EQ(locatePoint({Point(0, 0), Point(2, 0)}, Point(1, 0)), Containment::Boundary);
  EXPECT_EQ(locatePoint({Point(0, 0), Point(2, 0)}, Point(1, 1)), Containment::Outside);
}

TEST(Convexity, ConvexAndConcave)
{
  EXPECT_TRUE(isConvex(rectangle(0, 0, 2, 1)));
  EXPECT_FALSE(isConvex(lShape()));
  EXPECT_TRUE(isConvex({Point(0, 0), Point(1, 0), Point(0, 1)}));
}

TEST(Convexity, CollinearVerticesAllowed)
{
  const Polygon with_collinear = {Point(0, 0), Point(1, 0), Point(2, 0),
                                  Point(2, 2), Point(1, 2), Point(0, 2)};
  EXPECT_TRUE(isConvex(with_collinear));
  // A repeated vertex is a zero-length edge, not a turn.
  EXPECT_TRUE(isConvex({Point(0, 0), Point(1, 0), Point(1, 0), Point(1, 1), Point(0, 1)}));
}

TEST(Convexity, ClockwiseInput)
{
  const Polygon square = rectangle(0, 0, 2, 1);
  EXPECT_TRUE(isConvex(Polygon(square.rbegin(), square.rend())));
  const Polygon shape = lShape();
  EXPECT_FALSE(isConvex(Polygon(shape.rbegin(), shape.rend())));
}

TEST(Convexity, Degenerate)
{
  EXPECT_FALSE(isConvex({Point(0, 0), Point(1, 1)}));
  EXPECT_FALSE(isConvex({Point(0, 0), Point(1, 1), Point(2, 2)}));
  EXPECT_FALSE(isConvex({Point(0, 0), Point(2, 0), Point(1, 0)}));
  EXPECT_FALSE(isConvex({}));
}

TEST(Convexity, PentagramWindsTwice)
{
  Polygon star;
  for (int index = 0; index < 5; ++index) {
    const double angle = 2.0 * kPi * (2 * index) / 5.0;
    star.emplace_back(std::cos(angle), std::sin(angle));
  }
  EXPECT_FALSE(isConvex(star));
  EXPECT_FALSE(isSimple(star));
}

TEST(Simplicity, SimpleAndSelfIntersecting)
{
  EXPECT_TRUE(isSimple(rectangle(0, 0, 1, 1)));
  EXPECT_TRUE(isSimple(lShape()));
  const Polygon bow_tie = {Point(0, 0), Point(2, 2), Point(2, 0), Point(0, 2)};
  EXPECT_FALSE(isSimple(bow_tie));
  EXPECT_FALSE(isSimple({Point(0, 0), Point(2, 0), Point(1, 0)}));  // folds back on itself
  EXPECT_FALSE(isSimple({Point(0, 0), Point(1, 0)}));
  // Two squares touching at one vertex, traced as one boundary.
  const Polygon figure_eight = {Point(0, 0), Point(1, 0), Point(1, 1), Point(2, 1),
                                Point(2, 2), Point(1, 2), Point(1, 1), Point(0, 1)};
  EXPECT_FALSE(isSimple(figure_eight));
}

TEST(ConvexHull, DuplicatesAndCollinearPoints)
{
  const std::vector<Point> points = {Point(0, 0), Point(2, 0), Point(1, 0), Point(2, 2), Point(0, 2),
                                     Point(1, 1), Point(2, 2), Point(0, 0), Point(0, 1), Point(2, 1)};
  const Polygon hull = convexHull(points);
  const Polygon expected = {Point(0, 0), Point(2, 0), Point(2, 2), Point(0, 2)};
  EXPECT_EQ(hull, expected);
  EXPECT_DOUBLE_EQ(signedArea(hull), 4.0);
}

TEST(ConvexHull, DegenerateInputs)
{
  EXPECT_TRUE(convexHull({}).empty());
  EXPECT_EQ(convexHull({Point(1, 1), Point(1, 1)}), Polygon({Point(1, 1)}));
  const Polygon collinear = convexHull({Point(0, 0), Point(3, 3), Point(1, 1), Point(2, 2)});
  EXPECT_EQ(collinear, Polygon({Point(0, 0), Point(3, 3)}));
}

TEST(Width, RectangleTriangleRotatedSquareCollinear)
{
  EXPECT_NEAR(width(rectangle(0, 0, 2, 5)), 2.0, 1e-12);
  EXPECT_NEAR(width(rectangle(0, 0, 5, 2)), 2.0, 1e-12);
  // Right triangle 3-4-5: the smallest altitude is onto the hypotenuse, 2 * 6 / 5.
  EXPECT_NEAR(width({Point(0, 0), Point(4, 0), Point(0, 3)}), 2.4, 1e-12);
  const Pose2 rotation{3.0, -1.0, kPi / 6.0};
  Polygon rotated;
  for (const Point& corner : rectangle(0, 0, 1, 1)) {
    rotated.push_back(rotation.transform(corner));
  }
  EXPECT_NEAR(width(rotated), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(width({Point(0, 0), Point(1, 1), Point(2, 2)}), 0.0);
  EXPECT_DOUBLE_EQ(width({Point(0, 0), Point(1, 1)}), 0.0);
  // Concave input: the width is that of its hull (the L's hull is a pentagon 2 wide).
  EXPECT_NEAR(width(lShape()), 2.0, 1e-12);
}

TEST(Distance, ToBoundary)
{
  const Polygon square = rectangle(0, 0, 4, 4);
  EXPECT_DOUBLE_EQ(distanceToBoundary(square, Point(1, 2)), 1.0);
  EXPECT_DOUBLE_EQ(distanceToBoundary(square, Point(7, 8)), 5.0);
  EXPECT_DOUBLE_EQ(distanceToBoundary(square, Point(4, 2)), 0.0);
}

TEST(PolygonsIntersect, TouchingCounts)
{
  const Polygon left = rectangle(0, 0, 1, 1);
  EXPECT_TRUE(polygonsIntersect(left, rectangle(1, 0, 2, 1)));       // shared edge
  EXPECT_TRUE(polygonsIntersect(left, rectangle(1, 1, 2, 2)));       // shared vertex
  EXPECT_TRUE(polygonsIntersect(left, rectangle(1, 0.25, 2, 0.5)));  // partial edge contact
  EXPECT_TRUE(polygonsIntersect(left, rectangle(0.5, 0.5, 3, 3)));   // overlap
}

TEST(PolygonsIntersect, ContainmentAndDisjoint)
{
  const Polygon outer = rectangle(0, 0, 10, 10);
  const Polygon inner = rectangle(4, 4, 5, 5);
  EXPECT_TRUE(polygonsIntersect(outer, inner));
  EXPECT_TRUE(polygonsIntersect(inner, outer));
  EXPECT_FALSE(polygonsIntersect(rectangle(0, 0, 1, 1), rectangle(1.01, 0, 2, 1)));
  EXPECT_FALSE(polygonsIntersect(rectangle(0, 0, 1, 1), rectangle(1.5, 1.5, 2, 2)));
  // The second square sits in the L's notch without touching it.
  EXPECT_FALSE(polygonsIntersect(lShape(), rectangle(1.2, 1.2, 1.8, 1.8)));
  EXPECT_FALSE(polygonsIntersect({}, outer));
}

TEST(OffsetPolygon, EdgesMoveByTheDistanceAndCornersMeetOnBothLines)
{
  const Polygon grown = offsetPolygon(rectangle(0.0, 0.0, 2.0, 1.0), 0.1);
  ASSERT_EQ(grown.size(), 4U);
  EXPECT_TRUE(grown[0].isApprox(Point(-0.1, -0.1)));
  EXPECT_TRUE(grown[1].isApprox(Point(2.1, -0.1)));
  EXPECT_TRUE(grown[2].isApprox(Point(2.1, 1.1)));
  EXPECT_TRUE(grown[3].isApprox(Point(-0.1, 1.1)));
  const Polygon shrunk = offsetPolygon(rectangle(0.0, 0.0, 2.0, 1.0), -0.25);
  EXPECT_NEAR(area(shrunk), 1.5 * 0.5, 1e-12);
  // The concave corner of the L moves out along its bisector as well: onto both shifted edges.
  const Polygon l_grown = offsetPolygon(lShape(), 0.1);
  const Polygon l_expected{Point(-0.1, -0.1), Point(2.1, -0.1), Point(2.1, 1.1),
                           Point(1.1, 1.1),   Point(1.1, 2.1),  Point(-0.1, 2.1)};
  ASSERT_EQ(l_grown.size(), l_expected.size());
  for (std::size_t index = 0; index < l_grown.size(); ++index) {
    EXPECT_TRUE(l_grown[index].isApprox(l_expected[index])) << index;
  }
  EXPECT_TRUE(isSimple(l_grown));
}

TEST(OffsetPolygon, ASharpSpikeIsCappedAtTwiceTheDistance)
{
  // A thin triangle: its tip turns by nearly 180 degrees, where an uncapped mitre would run far out.
  const Polygon spike{Point(0.0, 0.0), Point(10.0, 0.5), Point(0.0, 1.0)};
  const Polygon grown = offsetPolygon(spike, 0.1);
  EXPECT_NEAR((grown[1] - spike[1]).norm(), 0.2, 1e-12);
  EXPECT_GT(grown[1].x(), spike[1].x());
  EXPECT_EQ(offsetPolygon(spike, 0.0), spike);
}

}  // namespace
}  // namespace ifar::geometry
