// The taut-bend rule (obstacle_set.hpp isTautBend) and the search that uses it on a complete reduced
// visibility graph (SearchGraph::fromCompleteGraph): the bends it drops are the ones a shortest path
// never takes, the lengths stay those of the unpruned search, and a graph that lacks an edge (as a merged
// online graph may) is still searched with every bend.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "planner/graph/visibility_builder.hpp"
#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;
using geometry::Vector;
using testing::mapFromRows;

// The corner (1, 1) of the blocked unit square [0, 1] x [0, 1] (counter-clockwise, blocked on the left):
// its wedge is the quadrant towards (-1, -1).
const LoopCorner kCorner{Point(1, 1), Point(1, 0), Point(0, 1), 0};

TEST(TautBend, WrappingTheCornerIsKept)
{
  // (2, -1) -> (1, 1) -> (-1, 2): the chord (2, -1) -> (-1, 2) crosses the square at (0.5, 0.5).
  EXPECT_TRUE(isTautBend(kCorner, Point(1, 1) - Point(2, -1), Point(-1, 2) - Point(1, 1)));
  // The mirror image: (-1, 2) -> (1, 1) -> (2, -1), a right turn with the wedge on the right.
  EXPECT_TRUE(isTautBend(kCorner, Point(1, 1) - Point(-1, 2), Point(2, -1) - Point(1, 1)));
  // Along the square's sides: (1, -2) up x = 1 to the corner, then west along y = 1.
  EXPECT_TRUE(isTautBend(kCorner, Vector(0, 1), Vector(-1, 0)));
  // Straight on past the corner, touching it.
  EXPECT_TRUE(isTautBend(kCorner, Vector(-1, 2), Vector(-1, 2)));
}

TEST(TautBend, TurningAwayFromTheWedgeIsDropped)
{
  // (2, -1) -> (1, 1) -> (2, 3): the wedge lies left of the way in, the turn is to the right; the chord
  // (2, -1) -> (2, 3) is free.
  EXPECT_FALSE(isTautBend(kCorner, Vector(-1, 2), Vector(1, 2)));
  // A left turn, but so sharp that the wedge lies right of the way out: (2, -1) -> (1, 1) -> (2, -2) runs
  // back down the square's east side, and the thin sector between the two lines is free.
  EXPECT_FALSE(isTautBend(kCorner, Vector(-1, 2), Vector(1, -3)));
  // Straight back.
  EXPECT_FALSE(isTautBend(kCorner, Vector(-1, 2), Vector(1, -2)));
}

/// Every query between lattice points of the map, with the unpruned and the pruned snapshot: the same
/// status and length. Returns the expansions of the two searches, summed.
std::pair<std::size_t, std::size_t> expectSameLengths(const std::vector<std::string>& rows)
{
  const PriorMap prior = buildPriorMap(mapFromRows(rows), 0.0);
  const SearchGraph full = SearchGraph::fromDvGraph(prior.graph);
  const SearchGraph taut = SearchGraph::fromCompleteGraph(prior.graph, prior.obstacles);
  SearchScratch scratch;
  std::pair<std::size_t, std::size_t> expansions{0, 0};
  const int width = static_cast<int>(rows.front().size());
  const int height = static_cast<int>(rows.size());
  for (int start = 0; start < (width + 1) * (height + 1); ++start) {
    for (int goal = 0; goal < (width + 1) * (height + 1); ++goal) {
      const Point from(start % (width + 1), start / (width + 1));
      const Point to(goal % (width + 1), goal / (width + 1));
      const SearchResult expected =
          findPath(full, prior.obstacles, from, to, scratch, {}, {}, InsideObstacle::Refuse);
      const SearchResult result =
          findPath(taut, prior.obstacles, from, to, scratch, {}, {}, InsideObstacle::Refuse);
      EXPECT_EQ(result.status, expected.status)
          << "(" << from.x() << ", " << from.y() << ") -> (" << to.x() << ", " << to.y() << ")";
      if (expected.status == SearchStatus::Found) {
        EXPECT_NEAR(result.length, expected.length, 1e-12)
            << "(" << from.x() << ", " << from.y() << ") -> (" << to.x() << ", " << to.y() << ")";
      }
      expansions.first += expected.expansions;
      expansions.second += result.expansions;
    }
  }
  return expansions;
}

TEST(TautSearch, SameLengthsAsEveryBendWithFewerExpansions)
{
  // Separate blocks, a wall with a gap, a diagonal touch (a double corner at (5, 3)) and a free pocket.
  const auto [full, taut] = expectSameLengths({
      "..........",
      ".@@...@...",
      ".@@....@..",
      "....@.....",
      "...@......",
      ".......@@@",
      "@@@.@@.@.@",
      ".......@@@",
  });
  EXPECT_LT(taut, full);
}

TEST(TautSearch, SameLengthsThroughDoubleCorners)
{
  // The double-corner maps (double_corner_test.cpp) in two orientations: paths squeeze past the pinch
  // points and bend at the cells' other corners.
  expectSameLengths({".....", "..@..", ".@...", ".....", "....."});
  expectSameLengths({".....", "..@..", "...@.", ".....", "....."});
}

TEST(TautSearch, OutlinesTouchingAtACornerKeepBothWedges)
{
  // Two squares that touch at (2, 2). From (1.5, 3) to (3, 1.5) the way bends at (2, 2) round the upper
  // right square (its corner's wedge is inside the left turn), a turn away from the lower left square's
  // corner at the same point: 2 * sqrt(1.25).
  const ObstacleSet obstacles({loopFromPolygon({Point(1, 1), Point(2, 1), Point(2, 2), Point(1, 2)}),
                               loopFromPolygon({Point(2, 2), Point(3, 2), Point(3, 3), Point(2, 3)})});
  DvGraph graph;
  addReducedVisibilityGraph(obstacles, graph);
  SearchScratch scratch;
  const SearchResult result = findPath(SearchGraph::fromCompleteGraph(graph, obstacles), obstacles,
                                       Point(1.5, 3), Point(3, 1.5), scratch);
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, std::sqrt(5.0), 1e-12);
}

TEST(TautSearch, AGraphThatLacksCornersKeepsEveryBend)
{
  // The unit square [0, 1]^2 and a wall x in [2, 2.2], y <= 0.5 between (3, 0.8) and (1.5, -1). The graph
  // has only the square's corner (1, 1), as a merged online graph may lack the wall's corners: the one way
  // it offers, (3, 0.8) -> (1, 1) -> (1.5, -1), turns left with the square right of the way out, a bend a
  // complete graph would cut short (over the wall's top). The planner's snapshot keeps it; the pruned
  // one, whose precondition this graph breaks, drops it.
  const ObstacleSet obstacles(
      {loopFromPolygon({Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)}),
       loopFromPolygon({Point(2, -5), Point(2.2, -5), Point(2.2, 0.5), Point(2, 0.5)})});
  DvGraph graph;
  Vertex corner;
  corner.position = Point(1, 1);
  corner.previous = Point(1, 0);
  corner.next = Point(0, 1);
  graph.addVertex(corner);
  const Point start(3, 0.8);
  const Point goal(1.5, -1);
  ASSERT_FALSE(isTautBend(LoopCorner{corner.position, corner.previous, corner.next, 0},
                          corner.position - start, goal - corner.position));
  SearchScratch scratch;
  const SearchResult kept = findPath(SearchGraph::fromDvGraph(graph), obstacles, start, goal, scratch);
  ASSERT_EQ(kept.status, SearchStatus::Found);
  EXPECT_NEAR(kept.length, (corner.position - start).norm() + (goal - corner.position).norm(), 1e-12);
  const SearchResult pruned =
      findPath(SearchGraph::fromCompleteGraph(graph, obstacles), obstacles, start, goal, scratch);
  EXPECT_EQ(pruned.status, SearchStatus::NoPath);
}

}  // namespace
}  // namespace ifar::graph
