// Starts and goals on a double corner (a lattice point where two blocked cells touch only diagonally),
// in the four orientations of one 5x5 map. GPPC's rule: such an end point leaves or is reached through
// the cell whose top-left corner it is, cell (x, y), the +x,+y quadrant (y points down in a .map). Where
// that cell is blocked (GPPC never poses such a query) it uses the +x,-y one (obstacle_set.hpp).

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;
using testing::mapFromRows;

struct Expected {
  Point target;
  double length;
};

/// Every query from `pinch` to each target and back: exact length, not snapped; with the planner's search
/// snapshot and with the one of a complete graph (taut bends only).
void expectLengths(const std::vector<std::string>& rows, const Point& pinch,
                   const std::vector<Expected>& expected)
{
  const PriorMap prior = buildPriorMap(mapFromRows(rows), 0.0);
  for (const SearchGraph& graph : {SearchGraph::fromDvGraph(prior.graph),
                                   SearchGraph::fromCompleteGraph(prior.graph, prior.obstacles)}) {
    SearchScratch scratch;
    for (const Expected& query : expected) {
      for (const bool from_pinch : {true, false}) {
        const Point& start = from_pinch ? pinch : query.target;
        const Point& goal = from_pinch ? query.target : pinch;
        const SearchResult result =
            findPath(graph, prior.obstacles, start, goal, scratch, {}, {}, InsideObstacle::Refuse);
        ASSERT_EQ(result.status, SearchStatus::Found)
            << "(" << start.x() << ", " << start.y() << ") -> (" << goal.x() << ", " << goal.y() << ")";
        EXPECT_FALSE(result.start_snapped || result.goal_snapped);
        EXPECT_NEAR(result.length, query.length, 1e-12)
            << "(" << start.x() << ", " << start.y() << ") -> (" << goal.x() << ", " << goal.y() << ")";
      }
    }
  }
}

const double kRootTwo = std::sqrt(2.0);
const double kRootTen = std::sqrt(10.0);

TEST(DoubleCorner, LeavesThroughTheCellWhoseTopLeftCornerItIs)
{
  // Cells (2,1) and (1,2) blocked; (2,2) is a GPPC double corner, free cells (1,1) and (2,2).
  // Only cell (2,2) is the start's:
  // - (3,3): straight through cell (2,2), sqrt(2);
  // - (1,2): not along y = 2 westwards (that leaves through cell (1,1)); down the east side of cell (1,2)
  //   to (2,3), along its bottom to (1,3), up to (1,2): 1 + 1 + 1 = 3;
  // - (1,1): as far as (1,3), then on up x = 1 past the corner (1,2): 1 + 1 + 2 = 4 (round cell (2,1)
  //   by (3,2), (3,1) also 4; every shortcut crosses a blocked cell);
  // - (0,0): (2,3), (1,3), then straight to (0,0) through column 0: 1 + 1 + sqrt(10) = 5.16228.
  expectLengths(
      {".....", "..@..", ".@...", ".....", "....."}, Point(2, 2),
      {{Point(3, 3), kRootTwo}, {Point(1, 2), 3.0}, {Point(1, 1), 4.0}, {Point(0, 0), 2.0 + kRootTen}});
}

TEST(DoubleCorner, MirroredLeftRightLeavesThroughThePlusXMinusYCell)
{
  // x mirrored: cells (2,1) and (3,2) blocked; the pinch (3,2) has cell (3,2) blocked, so it takes the
  // +x,-y cell (3,1):
  // - (4,1): through cell (3,1), sqrt(2); (5,0): through (3,1), (4,0), 2 sqrt(2);
  // - (4,2): east along the top of the blocked cell (3,2), the edge of its own cell: 1;
  // - (2,3): up to (3,1), west to (2,1), down x = 2 past the corner (2,2): 1 + 1 + 2 = 4 (or round cell
  //   (3,2) by (4,2), (4,3): also 4).
  expectLengths(
      {".....", "..@..", "...@.", ".....", "....."}, Point(3, 2),
      {{Point(4, 1), kRootTwo}, {Point(5, 0), 2.0 * kRootTwo}, {Point(4, 2), 1.0}, {Point(2, 3), 4.0}});
}

TEST(DoubleCorner, MirroredUpDownLeavesThroughThePlusXMinusYCell)
{
  // y mirrored: cells (1,2) and (2,3) blocked; the pinch (2,3) has cell (2,3) blocked and takes cell
  // (2,2), the mirror image of the first map's cell, so the lengths are the first map's mirrored:
  // - (3,2): sqrt(2); (1,3): up to (2,2), west to (1,2), down to (1,3): 3;
  // - (1,4): on down x = 1 past (1,3): 4; (0,5): (2,2), (1,2), then straight: 2 + sqrt(10).
  expectLengths(
      {".....", ".....", ".@...", "..@..", "....."}, Point(2, 3),
      {{Point(3, 2), kRootTwo}, {Point(1, 3), 3.0}, {Point(1, 4), 4.0}, {Point(0, 5), 2.0 + kRootTen}});
}

TEST(DoubleCorner, TurnedHalfWayLeavesThroughTheCellWhoseTopLeftCornerItIs)
{
  // Turned by 180 degrees: cells (3,2) and (2,3) blocked; the pinch (3,3) is a GPPC double corner again,
  // and its cell (3,3) is the mirror image of the first map's other free cell:
  // - (4,4): sqrt(2); (5,5): through (3,3), (4,4), 2 sqrt(2);
  // - (4,3): east along the bottom of the blocked cell (3,2), the edge of its own cell: 1;
  // - (2,2): east to (4,3), up to (4,2), west along y = 2 past (3,2): 1 + 1 + 2 = 4.
  expectLengths(
      {".....", ".....", "...@.", "..@..", "....."}, Point(3, 3),
      {{Point(4, 4), kRootTwo}, {Point(5, 5), 2.0 * kRootTwo}, {Point(4, 3), 1.0}, {Point(2, 2), 4.0}});
}

TEST(DoubleCorner, OnlyTheEndPointsOwnWedgeCountsAndNothingSqueezesThrough)
{
  const PriorMap prior = buildPriorMap(mapFromRows({".....", "..@..", ".@...", ".....", "....."}), 0.0);
  const ObstacleSet& obstacles = prior.obstacles;
  EXPECT_TRUE(obstacles.visible(Point(2, 2), Point(3, 3)));   // start in its own cell
  EXPECT_TRUE(obstacles.visible(Point(3, 3), Point(2, 2)));   // goal reached from its own cell
  EXPECT_TRUE(obstacles.visible(Point(2, 2), Point(4, 2)));   // along the edge of its own cell
  EXPECT_FALSE(obstacles.visible(Point(2, 2), Point(1, 1)));  // into the other free cell
  EXPECT_FALSE(obstacles.visible(Point(1, 1), Point(2, 2)));
  EXPECT_FALSE(obstacles.visible(Point(2, 2), Point(0, 2)));  // along the other cell's edge
  EXPECT_FALSE(obstacles.visible(Point(1, 1), Point(3, 3)));  // through the pinch: still refused
  EXPECT_FALSE(obstacles.visible(Point(3, 3), Point(1, 1)));
}

TEST(DoubleCorner, OutlinesThatOnlyTouchKeepEveryWedge)
{
  // Two separate squares touching at (1, 1): two visits there, but their blocked wedges (a quadrant each)
  // leave two free quadrants, so an end point there sees both and neither square.
  const ObstacleSet obstacles({loopFromPolygon({Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)}),
                               loopFromPolygon({Point(1, 1), Point(2, 1), Point(2, 2), Point(1, 2)})});
  EXPECT_TRUE(obstacles.visible(Point(1, 1), Point(0, 2)));
  EXPECT_TRUE(obstacles.visible(Point(1, 1), Point(2, 0)));
  EXPECT_TRUE(obstacles.visible(Point(2, 0), Point(1, 1)));
  EXPECT_FALSE(obstacles.visible(Point(1, 1), Point(1.5, 1.5)));
  EXPECT_FALSE(obstacles.visible(Point(1, 1), Point(0.5, 0.5)));
  EXPECT_FALSE(obstacles.visible(Point(1.5, 1.5), Point(1, 1)));
}

}  // namespace
}  // namespace ifar::graph
