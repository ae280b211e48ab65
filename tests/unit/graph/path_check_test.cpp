#include <vector>

#include <gtest/gtest.h>

#include "planner/graph/path_check.hpp"
#include "planner/graph/prior_map.hpp"
#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;
using testing::mapFromRows;

PathPoint at(const Point& position, VertexId vertex, std::uint32_t interaction = kNoInteraction)
{
  PathPoint point;
  point.position = position;
  point.vertex = vertex;
  point.interaction = interaction;
  return point;
}

// One blocked cell, [2, 3] x [2, 3], in a 5 x 5 map.
const ObstacleSet& oneCell()
{
  static const PriorMap prior =
      buildPriorMap(mapFromRows({".....", ".....", "..@..", ".....", "....."}), 0.0);
  return prior.obstacles;
}

TEST(PathCheck, OnlyGraphEdgesThroughAnObstacleAreReported)
{
  // The robot's link and the goal's cross the cell (the search tested them); so do 11-12 and the push
  // 13-14 (its plan answers for it); 12-13 and 14-15 are clear.
  const std::vector<PathPoint> path = {at(Point(4.5, 2.4), kNoVertex), at(Point(0.5, 2.5), 11),
                                       at(Point(4.5, 2.5), 12),        at(Point(4.5, 4.5), 13),
                                       at(Point(0.5, 0.5), 14, 0),     at(Point(0.5, 2.5), 15),
                                       at(Point(4.5, 2.7), kNoVertex)};
  const std::vector<std::pair<VertexId, VertexId>> blocked = blockedPathEdges(path, oneCell(), 0.25);
  ASSERT_EQ(blocked.size(), 1U);
  EXPECT_EQ(blocked[0], std::make_pair(VertexId{11}, VertexId{12}));
}

TEST(PathCheck, AnEdgeEndingJustInsideAnObstacleIsKeptWithinTheMargin)
{
  // 11-12 ends 0.1 inside the cell: a corner refreshed from a slightly different outline.
  const std::vector<PathPoint> path = {at(Point(0.5, 2.5), 11), at(Point(2.1, 2.5), 12)};
  EXPECT_TRUE(blockedPathEdges(path, oneCell(), 0.25).empty());
  EXPECT_EQ(blockedPathEdges(path, oneCell(), 0.0).size(), 1U);
  // The margin is at most a quarter of the edge: one ending half its length inside still counts.
  const std::vector<PathPoint> deep = {at(Point(1.6, 2.5), 11), at(Point(2.4, 2.5), 12)};
  EXPECT_EQ(blockedPathEdges(deep, oneCell(), 0.25).size(), 1U);
}

TEST(PathCheck, TheBlockedEdgesOfAVertexAreAllFound)
{
  DvGraph graph;
  Vertex vertex;
  vertex.position = Point(0.5, 2.5);
  const VertexId west = graph.addVertex(vertex);
  vertex.position = Point(4.5, 2.5);  // behind the cell
  const VertexId east = graph.addVertex(vertex);
  vertex.position = Point(4.5, 2.9);  // behind the cell
  const VertexId east_higher = graph.addVertex(vertex);
  vertex.position = Point(0.5, 4.5);  // in the clear
  const VertexId north = graph.addVertex(vertex);
  for (const VertexId other : {east, east_higher, north}) {
    ASSERT_EQ(graph.addVisibilityEdge(west, other), EdgeStatus::Added);
  }
  const std::vector<std::pair<VertexId, VertexId>> blocked = blockedEdgesOf(graph, west, oneCell(), 0.25);
  ASSERT_EQ(blocked.size(), 2U);
  EXPECT_EQ(blocked[0], std::make_pair(west, east));
  EXPECT_EQ(blocked[1], std::make_pair(west, east_higher));
  EXPECT_TRUE(blockedEdgesOf(graph, north, oneCell(), 0.25).empty());
  EXPECT_TRUE(blockedEdgesOf(graph, VertexId{99}, oneCell(), 0.25).empty());
}

}  // namespace
}  // namespace ifar::graph
