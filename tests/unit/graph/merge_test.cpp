#include <gtest/gtest.h>

#include "planner/graph/merge.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;

Vertex corner(double x, double y)
{
  Vertex vertex;
  vertex.kind = VertexKind::Corner;
  vertex.position = Point(x, y);
  vertex.previous = Point(x - 1, y);
  vertex.next = Point(x, y - 1);
  return vertex;
}

/// A copy of the vertex, or a default one when it is gone (keeps the tests free of null dereferences).
Vertex find(const DvGraph& graph, VertexId id)
{
  const Vertex* vertex = graph.vertex(id);
  return vertex != nullptr ? *vertex : Vertex{};
}

GraphSettings settings(int votes)
{
  GraphSettings result;
  result.votes = votes;
  result.association_distance_m = 0.5;
  return result;
}

TEST(Merge, FirstFrameAddsEverything)
{
  DvGraph global;
  LocalLayer local{{corner(1, 1), corner(4, 1)}, {{0, 1}}};
  std::vector<VertexId> mapping;
  const auto stats =
      mergeLocalIntoGlobal(local, SensorView{Point(0, 0), 10.0}, settings(3), global, &mapping);
  EXPECT_EQ(stats.added, 2u);
  EXPECT_EQ(stats.edges_added, 1u);
  EXPECT_EQ(global.vertexCount(), 2u);
  EXPECT_TRUE(global.hasVisibilityEdge(mapping[0], mapping[1]));
}

TEST(Merge, NearbyVertexAssociatedAndRefined)
{
  DvGraph global;
  LocalLayer first{{corner(1, 1)}, {}};
  std::vector<VertexId> mapping;
  mergeLocalIntoGlobal(first, SensorView{Point(0, 0), 10.0}, settings(3), global, &mapping);
  const VertexId id = mapping[0];
  LocalLayer second{{corner(1.2, 1.1)}, {}};
  const auto stats =
      mergeLocalIntoGlobal(second, SensorView{Point(0, 0), 10.0}, settings(3), global, &mapping);
  EXPECT_EQ(stats.associated, 1u);
  EXPECT_EQ(stats.added, 0u);
  EXPECT_EQ(mapping[0], id);  // stable id
  EXPECT_EQ(find(global, id).position, Point(1.2, 1.1));
  // Beyond the association distance it is a new vertex.
  LocalLayer far{{corner(3, 3)}, {}};
  EXPECT_EQ(mergeLocalIntoGlobal(far, SensorView{Point(0, 0), 10.0}, settings(3), global).added, 1u);
}

TEST(Merge, UnseenInViewRemovedAfterVotes)
{
  DvGraph global;
  std::vector<VertexId> mapping;
  mergeLocalIntoGlobal(LocalLayer{{corner(1, 1), corner(5, 5)}, {{0, 1}}}, SensorView{Point(0, 0), 10.0},
                       settings(3), global, &mapping);
  const VertexId vanished = mapping[1];
  // The corner at (5,5) is in view but no longer observed: 3 frames remove it, not 2.
  const LocalLayer only_first{{corner(1, 1)}, {}};
  for (int frame = 1; frame <= 2; ++frame) {
    mergeLocalIntoGlobal(only_first, SensorView{Point(0, 0), 10.0}, settings(3), global);
    EXPECT_TRUE(global.contains(vanished)) << "frame " << frame;
    EXPECT_EQ(find(global, vanished).unseen_votes, frame);
  }
  const auto stats = mergeLocalIntoGlobal(only_first, SensorView{Point(0, 0), 10.0}, settings(3), global);
  EXPECT_EQ(stats.removed, 1u);
  EXPECT_FALSE(global.contains(vanished));
  EXPECT_EQ(global.visibilityEdgeCount(), 0u);
}

TEST(Merge, SeenAgainResetsVotes)
{
  DvGraph global;
  std::vector<VertexId> mapping;
  const LocalLayer both{{corner(1, 1), corner(5, 5)}, {}};
  mergeLocalIntoGlobal(both, SensorView{Point(0, 0), 10.0}, settings(3), global, &mapping);
  const LocalLayer only_first{{corner(1, 1)}, {}};
  mergeLocalIntoGlobal(only_first, SensorView{Point(0, 0), 10.0}, settings(3), global);
  mergeLocalIntoGlobal(only_first, SensorView{Point(0, 0), 10.0}, settings(3), global);
  mergeLocalIntoGlobal(both, SensorView{Point(0, 0), 10.0}, settings(3), global);
  EXPECT_EQ(find(global, mapping[1]).unseen_votes, 0);
  mergeLocalIntoGlobal(only_first, SensorView{Point(0, 0), 10.0}, settings(3), global);
  EXPECT_TRUE(global.contains(mapping[1]));
}

TEST(Merge, OutOfViewKept)
{
  DvGraph global;
  std::vector<VertexId> mapping;
  mergeLocalIntoGlobal(LocalLayer{{corner(1, 1), corner(50, 50)}, {{0, 1}}}, SensorView{Point(0, 0), 100.0},
                       settings(2), global, &mapping);
  // The robot drove on: (50,50) is now outside a 10 m view and must survive any number of frames.
  for (int frame = 0; frame < 5; ++frame) {
    mergeLocalIntoGlobal(LocalLayer{{corner(1, 1)}, {}}, SensorView{Point(0, 0), 10.0}, settings(2), global);
  }
  EXPECT_TRUE(global.contains(mapping[1]));
  EXPECT_EQ(find(global, mapping[1]).unseen_votes, 0);
  EXPECT_TRUE(global.hasVisibilityEdge(mapping[0], mapping[1]));  // into unobserved space: kept
}

TEST(Merge, ContradictedEdgeRemoved)
{
  DvGraph global;
  std::vector<VertexId> mapping;
  mergeLocalIntoGlobal(LocalLayer{{corner(1, 1), corner(4, 1)}, {{0, 1}}}, SensorView{Point(0, 0), 10.0},
                       settings(3), global, &mapping);
  // Both corners observed again but an obstacle now blocks the line between them.
  const auto stats = mergeLocalIntoGlobal(LocalLayer{{corner(1, 1), corner(4, 1)}, {}},
                                          SensorView{Point(0, 0), 10.0}, settings(3), global);
  EXPECT_EQ(stats.edges_removed, 1u);
  EXPECT_FALSE(global.hasVisibilityEdge(mapping[0], mapping[1]));
}

TEST(Merge, NonFiniteLocalVertexSkipped)
{
  DvGraph global;
  LocalLayer local{{corner(1, 1), corner(std::numeric_limits<double>::quiet_NaN(), 1)}, {{0, 1}}};
  const auto stats = mergeLocalIntoGlobal(local, SensorView{Point(0, 0), 10.0}, settings(3), global);
  EXPECT_EQ(stats.added, 1u);
  EXPECT_EQ(stats.skipped, 2u);  // the vertex and its edge
  EXPECT_EQ(global.visibilityEdgeCount(), 0u);
}

}  // namespace
}  // namespace ifar::graph

namespace ifar::graph {
namespace {

TEST(Merge, LocalVertexBeyondViewRadiusStillAssociated)
{
  // The local layer reaches farther than the voting radius: its far corners must not be duplicated.
  DvGraph global;
  const LocalLayer layer{{corner(1, 1), corner(28, 0)}, {}};
  GraphSettings config;
  config.votes = 3;
  for (int frame = 0; frame < 4; ++frame) {
    mergeLocalIntoGlobal(layer, SensorView{Point(0, 0), 25.0}, config, global);
  }
  EXPECT_EQ(global.vertexCount(), 2u);
}

}  // namespace
}  // namespace ifar::graph
