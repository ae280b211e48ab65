// memoryBytes of the graph's structures: what they hold on the heap, by capacity.

#include <vector>

#include <gtest/gtest.h>

#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph {
namespace {

TEST(GraphMemory, DvGraphCountsSlotsAdjacencyAndInteractionEdges)
{
  DvGraph graph;
  EXPECT_EQ(graph.memoryBytes(), 0u);
  Vertex vertex;
  const VertexId first = graph.addVertex(vertex);
  vertex.position = geometry::Point(3, 4);
  const VertexId second = graph.addVertex(vertex);
  ASSERT_EQ(graph.addVisibilityEdge(first, second), EdgeStatus::Added);
  // Two slots and two adjacency lists (capacity 2 after two insertions), one link in each list.
  EXPECT_EQ(graph.memoryBytes(),
            2 * sizeof(Vertex) + 2 * sizeof(std::vector<VisibilityLink>) + 2 * sizeof(VisibilityLink));
  InteractionEdge push;
  push.from = first;
  push.to = second;
  ASSERT_TRUE(graph.addInteractionEdge(push).has_value());
  EXPECT_EQ(graph.memoryBytes(), 2 * sizeof(Vertex) + 2 * sizeof(std::vector<VisibilityLink>) +
                                     2 * sizeof(VisibilityLink) + sizeof(InteractionEdge));
}

TEST(GraphMemory, GrowsWithTheMap)
{
  const PriorMap small = buildPriorMap(testing::mapFromRows({"...", ".@.", "..."}), 0.0);
  const PriorMap larger =
      buildPriorMap(testing::mapFromRows({".......", ".@...@.", ".......", ".@...@.", "......."}), 0.0);
  // Empty: only the index's one offset.
  EXPECT_EQ(ObstacleSet({}).memoryBytes(), sizeof(std::uint32_t));
  EXPECT_LT(small.obstacles.memoryBytes(), larger.obstacles.memoryBytes());
  EXPECT_LT(small.graph.memoryBytes(), larger.graph.memoryBytes());
  EXPECT_EQ(SearchGraph().memoryBytes(), 0u);
  EXPECT_LT(SearchGraph::fromDvGraph(small.graph).memoryBytes(),
            SearchGraph::fromDvGraph(larger.graph).memoryBytes());
}

}  // namespace
}  // namespace ifar::graph
