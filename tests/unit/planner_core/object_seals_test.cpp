// Seals kept with a movable object: the outline takes in the gap's free cells, bind adds up, release hands
// the whole seal back once.

#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/polygon.hpp"
#include "planner/core/object_seals.hpp"

namespace ifar::planner {
namespace {

geometry::Polygon rectangle(double x0, double y0, double x1, double y1)
{
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

TEST(ObjectSeals, TheOutlineTakesInTheGapCells)
{
  ObjectSeals seals(0.2);
  const geometry::Polygon outline = rectangle(0.0, 0.0, 1.0, 1.0);
  EXPECT_EQ(seals.grown(3, outline), outline);  // no seal: as it is

  // A lane west of the box, cells at x = -0.3 and -0.1 (0.2 m cells): the hull reaches x = -0.4.
  const std::vector<geometry::Point> gap{{-0.3, 0.5}, {-0.1, 0.5}};
  const std::vector<geometry::Point> cells{{-0.5, 0.5}, {-0.3, 0.5}, {-0.1, 0.5}, {0.1, 0.5}};
  seals.bind(3, gap, cells);
  EXPECT_TRUE(seals.holds(3));
  EXPECT_FALSE(seals.holds(4));
  const geometry::Polygon grown = seals.grown(3, outline);
  EXPECT_NEAR(geometry::area(grown), 1.0 + 0.4 * 1.0 - 2.0 * 0.5 * 0.4 * 0.4, 1e-9);  // box + trapezoid
  EXPECT_TRUE(geometry::containsPoint(grown, geometry::Point(-0.35, 0.5)));
  EXPECT_FALSE(geometry::containsPoint(grown, geometry::Point(-0.45, 0.5)));
  EXPECT_FALSE(geometry::containsPoint(grown, geometry::Point(-0.35, 0.05)));
  // Other objects keep their outline.
  EXPECT_EQ(seals.grown(4, outline), outline);
}

TEST(ObjectSeals, BindAddsUpAndReleaseHandsTheCellsBackOnce)
{
  ObjectSeals seals(0.15);
  seals.bind(3, {{2.0, 0.0}}, {{2.0, 0.0}, {2.15, 0.0}});
  seals.bind(3, {{0.0, 2.0}}, {{0.0, 2.0}});
  seals.bind(5, {{9.0, 9.0}}, {{9.0, 9.0}});
  EXPECT_EQ(seals.size(), 2U);
  const geometry::Polygon grown = seals.grown(3, rectangle(0.0, 0.0, 1.0, 1.0));
  EXPECT_TRUE(geometry::containsPoint(grown, geometry::Point(2.05, 0.0)));
  EXPECT_TRUE(geometry::containsPoint(grown, geometry::Point(0.0, 2.05)));

  EXPECT_EQ(seals.release(3).size(), 3U);
  EXPECT_FALSE(seals.holds(3));
  EXPECT_TRUE(seals.release(3).empty());
  EXPECT_EQ(seals.size(), 1U);
  seals.clear();
  EXPECT_FALSE(seals.holds(5));
}

}  // namespace
}  // namespace ifar::planner
