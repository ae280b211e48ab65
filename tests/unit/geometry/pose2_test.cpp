#include "common/geometry/pose2.hpp"

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"

namespace ifar::geometry {
namespace {

TEST(WrapAngle, KeepsAnglesInsideTheRange)
{
  EXPECT_DOUBLE_EQ(wrapAngle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(wrapAngle(1.0), 1.0);
  EXPECT_DOUBLE_EQ(wrapAngle(-1.0), -1.0);
}

TEST(WrapAngle, WrapsWholeTurns)
{
  EXPECT_NEAR(wrapAngle(2.0 * kPi + 0.5), 0.5, 1e-12);
  EXPECT_NEAR(wrapAngle(-2.0 * kPi - 0.5), -0.5, 1e-12);
  EXPECT_NEAR(wrapAngle(7.0 * kPi / 2.0), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(wrapAngle(100.0 * kPi + 0.25), 0.25, 1e-9);
}

TEST(WrapAngle, BoundaryIsPlusPi)
{
  EXPECT_DOUBLE_EQ(wrapAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(-kPi), kPi);
  EXPECT_NEAR(wrapAngle(3.0 * kPi), kPi, 1e-12);
}

TEST(Pose2, TransformRotatesThenTranslates)
{
  const Pose2 pose{1.0, 2.0, kPi / 2.0};
  const Point mapped = pose.transform(Point(1.0, 0.0));
  EXPECT_NEAR(mapped.x(), 1.0, 1e-12);
  EXPECT_NEAR(mapped.y(), 3.0, 1e-12);
  const Point back = pose.inverseTransform(mapped);
  EXPECT_NEAR(back.x(), 1.0, 1e-12);
  EXPECT_NEAR(back.y(), 0.0, 1e-12);
}

TEST(Pose2, ComposeChainsFrames)
{
  const Pose2 first{1.0, 0.0, kPi / 2.0};
  const Pose2 second{2.0, 0.0, kPi / 2.0};
  const Pose2 composed = first.compose(second);
  EXPECT_NEAR(composed.x, 1.0, 1e-12);
  EXPECT_NEAR(composed.y, 2.0, 1e-12);
  EXPECT_NEAR(composed.heading, kPi, 1e-12);
  const Point body(0.3, -0.7);
  const Point direct = composed.transform(body);
  const Point chained = first.transform(second.transform(body));
  EXPECT_NEAR(direct.x(), chained.x(), 1e-12);
  EXPECT_NEAR(direct.y(), chained.y(), 1e-12);
}

TEST(Pose2, InverseUndoesThePose)
{
  const Pose2 pose{3.0, -4.0, 2.5};
  const Pose2 identity = pose.compose(pose.inverse());
  EXPECT_NEAR(identity.x, 0.0, 1e-12);
  EXPECT_NEAR(identity.y, 0.0, 1e-12);
  EXPECT_NEAR(identity.heading, 0.0, 1e-12);
  const Pose2 other_way = pose.inverse().compose(pose);
  EXPECT_NEAR(other_way.x, 0.0, 1e-12);
  EXPECT_NEAR(other_way.y, 0.0, 1e-12);
  EXPECT_NEAR(other_way.heading, 0.0, 1e-12);
}

TEST(Pose2, RoundTripsPointsThroughManyPoses)
{
  for (int step = -8; step <= 8; ++step) {
    const Pose2 pose{0.5 * step, -0.25 * step, 0.7 * step};
    const Point parent(1.5 - step, 2.0 + 0.1 * step);
    const Point round_trip = pose.transform(pose.inverseTransform(parent));
    EXPECT_NEAR(round_trip.x(), parent.x(), 1e-12);
    EXPECT_NEAR(round_trip.y(), parent.y(), 1e-12);
    const Point via_inverse = pose.inverse().transform(parent);
    const Point via_inverse_transform = pose.inverseTransform(parent);
    EXPECT_NEAR(via_inverse.x(), via_inverse_transform.x(), 1e-12);
    EXPECT_NEAR(via_inverse.y(), via_inverse_transform.y(), 1e-12);
    EXPECT_GT(pose.compose(Pose2{}).heading, -kPi);
    EXPECT_LE(pose.compose(Pose2{}).heading, kPi);
  }
}

}  // namespace
}  // namespace ifar::geometry
