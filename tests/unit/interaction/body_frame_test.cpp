#include "planner/interaction/body_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry/pose2.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;
using geometry::Pose2;

TEST(BodyToWorldTest, CarriesEveryPointToTheSameBitsAsPose2Transform)
{
  // Collision and goal tests take the same decisions whichever of the two carried the outline there.
  int compared = 0;
  for (int pose_index = 0; pose_index < 50; ++pose_index) {
    const Pose2 pose{-3.7 + 0.31 * pose_index, 12.9 - 0.17 * pose_index, -3.1 + 0.127 * pose_index};
    const BodyToWorld to_world(pose);
    for (int point_index = 0; point_index < 40; ++point_index) {
      const Point body(std::sin(0.7 * point_index) * 1.3, std::cos(1.9 * point_index) * 0.45);
      const Point expected = pose.transform(body);
      const Point carried = to_world(body);
      EXPECT_EQ(carried.x(), expected.x()) << "pose " << pose_index << " point " << point_index;
      EXPECT_EQ(carried.y(), expected.y()) << "pose " << pose_index << " point " << point_index;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 2000);
  // A quarter turn: (1, 0) in the body is (0, 1) from the pose's position.
  const Point turned = BodyToWorld(Pose2{2.0, 3.0, M_PI / 2.0})(Point(1.0, 0.0));
  EXPECT_NEAR(turned.x(), 2.0, 1e-12);
  EXPECT_NEAR(turned.y(), 4.0, 1e-12);
}

}  // namespace
}  // namespace ifar::interaction
