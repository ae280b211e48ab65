// sealPassage: where a passage the vehicle could not get through is closed, on hand-made (inflated)
// obstacles.

#include <algorithm>

#include <gtest/gtest.h>

#include "planner/core/passage_seal.hpp"

namespace ifar::planner {
namespace {

/// Two blocks leaving a 0.3 m channel at x in [2.0, 2.3] for y in [0, 1].
graph::ObstacleSet channel()
{
  std::vector<graph::ObstacleLoop> loops;
  loops.push_back(graph::loopFromPolygon({{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {0.0, 1.0}}));
  loops.push_back(graph::loopFromPolygon({{2.3, 0.0}, {4.0, 0.0}, {4.0, 1.0}, {2.3, 1.0}}));
  return graph::ObstacleSet(std::move(loops));
}

/// Two blocks pinching to a 0.3 m gap at (2.15, 0.5): vertices at (2.0, 0.5) and (2.3, 0.5), the gap
/// wider above and below.
graph::ObstacleSet pinch()
{
  std::vector<graph::ObstacleLoop> loops;
  loops.push_back(graph::loopFromPolygon({{0.0, 0.0}, {1.9, 0.0}, {2.0, 0.5}, {1.9, 1.0}, {0.0, 1.0}}));
  loops.push_back(graph::loopFromPolygon({{2.4, 0.0}, {4.0, 0.0}, {4.0, 1.0}, {2.4, 1.0}, {2.3, 0.5}}));
  return graph::ObstacleSet(std::move(loops));
}

TEST(PassageSeal, ClosesTheNarrowestPointAcrossTheSegmentIntoTheInflation)
{
  const graph::ObstacleSet obstacles = pinch();
  const std::optional<PassageSeal> seal =
      sealPassage(obstacles, geometry::Point(2.15, -1.5), geometry::Point(2.15, 2.5), 0.35, 0.1);
  ASSERT_TRUE(seal);
  EXPECT_NEAR(seal->centre.x(), 2.15, 1e-9);
  EXPECT_NEAR(seal->centre.y(), 0.5, 1e-9);
  EXPECT_NEAR(seal->half_width_m, 0.15, 1e-9);
  // A row across (along x), 0.1 m apart, through the centre, from right (+x) to left.
  ASSERT_GE(seal->cells.size(), 3U);
  for (std::size_t index = 0; index < seal->cells.size(); ++index) {
    EXPECT_NEAR(seal->cells[index].y(), 0.5, 1e-9);
    if (index > 0) {
      EXPECT_NEAR(seal->cells[index - 1].x() - seal->cells[index].x(), 0.1, 1e-9);
    }
    // Free, or inside an inflated block by at most the inflation less a cell.
    const geometry::Point& cell = seal->cells[index];
    EXPECT_TRUE(!obstacles.isBlocked(cell) || obstacles.distanceToBoundary(cell) <= 0.25 + 1e-9) << cell.x();
  }
  // Into both blocks (past the free gap the picture shows), and no cell beyond stays short of the obstacle.
  EXPECT_GT(seal->cells.front().x(), 2.3 + 0.1);
  EXPECT_LT(seal->cells.back().x(), 2.0 - 0.1);
  const std::vector<geometry::Point> beyond_ends{seal->cells.front() + geometry::Point(0.1, 0.0),
                                                 seal->cells.back() - geometry::Point(0.1, 0.0)};
  for (const geometry::Point& beyond : beyond_ends) {
    EXPECT_TRUE(obstacles.isBlocked(beyond));
    EXPECT_GT(obstacles.distanceToBoundary(beyond), 0.25) << beyond.x();
  }
}

TEST(PassageSeal, ReachesAcrossPastAnObstacleTheSegmentCrosses)
{
  // A bar x 0 .. 2.0, y 1.0 .. 1.3 (inflated) across the segment, a wall from x 2.2: the vehicle north of
  // the bar, its target south, the gap between the bar's end and the wall is what it could not pass. The
  // narrowest free point lies a step off the bar, so its nearest obstacle is the bar, along the segment;
  // the row must still reach across into the wall's inflation, closing the gap's mouth.
  std::vector<graph::ObstacleLoop> loops;
  loops.push_back(graph::loopFromPolygon({{0.0, 1.0}, {2.0, 1.0}, {2.0, 1.3}, {0.0, 1.3}}));
  loops.push_back(graph::loopFromPolygon({{2.2, -2.0}, {4.0, -2.0}, {4.0, 4.0}, {2.2, 4.0}}));
  const graph::ObstacleSet obstacles(std::move(loops));
  const std::optional<PassageSeal> seal =
      sealPassage(obstacles, geometry::Point(1.6, 2.3), geometry::Point(1.6, -0.5), 0.35, 0.15);
  ASSERT_TRUE(seal);
  EXPECT_LT(seal->half_width_m, 0.1);
  EXPECT_TRUE(seal->centre.y() < 1.0 || seal->centre.y() > 1.3);
  // The row ends inside the wall's inflation: the gap (x 2.0 .. 2.2) is closed at the bar's side.
  double most_x = -1e9;
  for (const geometry::Point& cell : seal->cells) {
    most_x = std::max(most_x, cell.x());
  }
  EXPECT_GT(most_x, 2.2) << "row ends at x " << most_x;
}

TEST(PassageSeal, KeepsClearOfTheVehicle)
{
  // The vehicle stands in the channel's mouth: the seal starts inflation + a cell further on.
  const std::optional<PassageSeal> seal =
      sealPassage(channel(), geometry::Point(2.15, 0.1), geometry::Point(2.15, 2.5), 0.35, 0.1);
  ASSERT_TRUE(seal);
  EXPECT_GE(seal->centre.y(), 0.1 + 0.45 - 1e-9);
  EXPECT_NEAR(seal->half_width_m, 0.15, 1e-9);
}

TEST(PassageSeal, NothingToSealGivesNoSeal)
{
  const graph::ObstacleSet obstacles = channel();
  // Shorter than the distance kept clear of the vehicle.
  EXPECT_FALSE(sealPassage(obstacles, geometry::Point(2.15, -0.2), geometry::Point(2.15, 0.1), 0.35, 0.1));
  // Inside a block all along.
  EXPECT_FALSE(sealPassage(obstacles, geometry::Point(0.5, 0.5), geometry::Point(1.8, 0.5), 0.35, 0.1));
  // No obstacle anywhere: nothing narrow to close.
  EXPECT_FALSE(sealPassage(graph::ObstacleSet({}), geometry::Point(0, 0), geometry::Point(3, 0), 0.35, 0.1));
  // Bad input.
  EXPECT_FALSE(sealPassage(obstacles, geometry::Point(2.15, -1.5), geometry::Point(2.15, -1.5), 0.35, 0.1));
  EXPECT_FALSE(sealPassage(obstacles, geometry::Point(2.15, -1.5), geometry::Point(2.15, 2.5), 0.35, 0.0));
}

TEST(PassageSeal, RemovesTheEdgesThroughIt)
{
  const std::optional<PassageSeal> seal =
      sealPassage(pinch(), geometry::Point(2.15, -1.5), geometry::Point(2.15, 2.5), 0.35, 0.1);
  ASSERT_TRUE(seal);
  // The line across reaches the inflation beyond the outer cells.
  EXPECT_NEAR(seal->across.start.x() - seal->cells.front().x(), 0.35, 1e-9);
  EXPECT_NEAR(seal->cells.back().x() - seal->across.end.x(), 0.35, 1e-9);
  graph::DvGraph graph;
  const auto vertexAt = [&graph](double x, double y) {
    graph::Vertex vertex;
    vertex.position = geometry::Point(x, y);
    return graph.addVertex(vertex);
  };
  const graph::VertexId south = vertexAt(2.15, -1.0);
  const graph::VertexId north = vertexAt(2.0, 3.0);  // out of view, say: the merge would keep the edge
  const graph::VertexId west = vertexAt(-1.0, -1.0);
  ASSERT_EQ(graph.addVisibilityEdge(south, north), graph::EdgeStatus::Added);
  ASSERT_EQ(graph.addVisibilityEdge(south, west), graph::EdgeStatus::Added);
  EXPECT_EQ(removeEdgesThroughSeal(*seal, graph), 1U);
  EXPECT_FALSE(graph.hasVisibilityEdge(south, north));
  EXPECT_TRUE(graph.hasVisibilityEdge(south, west));
}

}  // namespace
}  // namespace ifar::planner
