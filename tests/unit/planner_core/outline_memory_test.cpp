// The outline memory: partial views of one object add up to the hull of what was seen, the vehicle at the
// object restarts it (a pushed object moves), a forgotten object starts again, and 0 keeps nothing.

#include <gtest/gtest.h>

#include "common/geometry/polygon.hpp"
#include "planner/core/outline_memory.hpp"

namespace ifar::planner {
namespace {

geometry::Polygon rectangle(double x0, double y0, double x1, double y1)
{
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

const geometry::Point kFarAway(-10.0, 0.0);

TEST(OutlineMemory, PartialViewsAddUpToTheirHull)
{
  OutlineMemory memory(1.0);
  // A 1.0 m x 1.2 m box seen first by its lower part, then by its upper part.
  EXPECT_DOUBLE_EQ(geometry::area(memory.remember(7, rectangle(0.0, 0.0, 1.0, 0.4), kFarAway)), 0.4);
  const geometry::Polygon both = memory.remember(7, rectangle(0.0, 0.8, 1.0, 1.2), kFarAway);
  EXPECT_DOUBLE_EQ(geometry::area(both), 1.2);
  EXPECT_TRUE(geometry::containsPoint(both, geometry::Point(0.5, 0.6)));  // the lane between the two views
  // A smaller view later does not shrink it.
  EXPECT_DOUBLE_EQ(geometry::area(memory.remember(7, rectangle(0.2, 0.5, 0.4, 0.7), kFarAway)), 1.2);
  // Other objects have their own.
  EXPECT_DOUBLE_EQ(geometry::area(memory.remember(8, rectangle(5.0, 0.0, 5.5, 0.5), kFarAway)), 0.25);
  EXPECT_EQ(memory.size(), 2U);
}

TEST(OutlineMemory, TheVehicleAtTheObjectRestartsItsHull)
{
  OutlineMemory memory(1.0);
  memory.remember(7, rectangle(0.0, 0.0, 1.0, 1.2), kFarAway);
  // 0.9 m from the outline of the frame: pushing distance, the object may move.
  const geometry::Polygon near = memory.remember(7, rectangle(0.5, 0.0, 1.5, 1.2), geometry::Point(2.4, 0.6));
  EXPECT_DOUBLE_EQ(geometry::area(near), 1.2);
  EXPECT_FALSE(geometry::containsPoint(near, geometry::Point(0.25, 0.6)));  // where it was
  // 1.1 m away it adds up again.
  EXPECT_DOUBLE_EQ(
      geometry::area(memory.remember(7, rectangle(1.5, 0.0, 2.0, 1.2), geometry::Point(3.1, 0.6))), 1.8);
}

TEST(OutlineMemory, AForgottenObjectStartsAgainAndZeroKeepsNothing)
{
  OutlineMemory memory(1.0);
  memory.remember(7, rectangle(0.0, 0.0, 1.0, 1.0), kFarAway);
  memory.forget(7);
  EXPECT_EQ(memory.size(), 0U);
  EXPECT_DOUBLE_EQ(geometry::area(memory.remember(7, rectangle(3.0, 0.0, 3.5, 0.5), kFarAway)), 0.25);

  OutlineMemory off(0.0);
  const geometry::Polygon concave = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {1.0, 1.0}, {0.0, 2.0}};
  off.remember(7, rectangle(0.0, 0.0, 5.0, 5.0), kFarAway);
  EXPECT_EQ(off.remember(7, concave, kFarAway), concave);  // as seen, not even its hull
  EXPECT_EQ(off.size(), 0U);
}

}  // namespace
}  // namespace ifar::planner
