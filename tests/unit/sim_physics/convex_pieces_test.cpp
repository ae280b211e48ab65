#include "sim/physics/convex_pieces.hpp"

#include <gtest/gtest.h>

namespace ifar::sim::physics {
namespace {

using geometry::Point;

TEST(ConvexPieces, ConvexPolygonStaysWhole)
{
  const geometry::Polygon square{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  const auto pieces = convexPieces(square);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(signedPolygonArea(pieces[0]), 1.0);
}

TEST(ConvexPieces, ClockwiseInputComesBackCounterClockwise)
{
  const geometry::Polygon square{Point(0, 0), Point(0, 1), Point(1, 1), Point(1, 0)};
  const auto pieces = convexPieces(square);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(signedPolygonArea(pieces[0]), 1.0);
}

TEST(ConvexPieces, LShapeSplitsIntoTrianglesCoveringItsArea)
{
  // An L of area 3: concave, so it is ear-clipped.
  const geometry::Polygon shape{Point(0, 0), Point(2, 0), Point(2, 1), Point(1, 1), Point(1, 2), Point(0, 2)};
  const auto pieces = convexPieces(shape);
  ASSERT_EQ(pieces.size(), 4u);
  double total = 0.0;
  for (const auto& piece : pieces) {
    ASSERT_EQ(piece.size(), 3u);
    EXPECT_GT(signedPolygonArea(piece), 0.0);
    total += signedPolygonArea(piece);
  }
  EXPECT_NEAR(total, 3.0, 1e-12);
}

TEST(ConvexPieces, ConvexPolygonWithTooManyVerticesIsSplit)
{
  geometry::Polygon circle;
  for (int index = 0; index < 12; ++index) {
    const double angle = 2.0 * M_PI * index / 12.0;
    circle.emplace_back(std::cos(angle), std::sin(angle));
  }
  const auto pieces = convexPieces(circle, 8);
  EXPECT_EQ(pieces.size(), 10u);
  double total = 0.0;
  for (const auto& piece : pieces) {
    total += signedPolygonArea(piece);
  }
  EXPECT_NEAR(total, signedPolygonArea(circle), 1e-12);
}

TEST(ConvexPieces, DegenerateInputGivesNoPieces)
{
  EXPECT_TRUE(convexPieces({Point(0, 0), Point(1, 0), Point(2, 0)}).empty());
  EXPECT_TRUE(convexPieces({}).empty());
}

}  // namespace
}  // namespace ifar::sim::physics
