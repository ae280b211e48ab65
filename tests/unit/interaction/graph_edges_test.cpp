#include "planner/interaction/graph_edges.hpp"

#include <gtest/gtest.h>

#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

InteractionSettings defaultSettings()
{
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  settings.search.time_budget_s = 1.0;
  return settings;
}

TEST(InteractionGraphTest, DoorwayGivesTwoWaypointsAndTwoDirectedEdges)
{
  graph::DvGraph graph;
  const auto interactions =
      planObjectInteractions(test::doorwayScene(), 0, ObjectPhysics{0.4, 20.0}, defaultSettings());
  const InsertedInteractions inserted = insertInteractions(graph, 7, interactions, 0);
  ASSERT_EQ(inserted.waypoint_vertices.size(), 2U);
  ASSERT_EQ(inserted.edges.size(), 2U);
  EXPECT_EQ(graph.interactionEdgeCount(), 2U);
  const graph::InteractionEdge& forward = graph.interactionEdges()[inserted.edges[0]];
  const graph::InteractionEdge& backward = graph.interactionEdges()[inserted.edges[1]];
  EXPECT_EQ(forward.from, backward.to);
  EXPECT_EQ(forward.to, backward.from);
  EXPECT_EQ(forward.object_id, 7);
  EXPECT_DOUBLE_EQ(forward.cost, interactions.plans[0].plan.cost);
  EXPECT_EQ(backward.push_plan, 1U);
  const graph::Vertex* waypoint = graph.vertex(inserted.waypoint_vertices[0]);
  ASSERT_NE(waypoint, nullptr);
  const graph::VertexKind kind = waypoint->kind;
  EXPECT_TRUE(kind == graph::VertexKind::TopologicalWaypoint);
}

TEST(InteractionGraphTest, TJunctionGivesThreeWaypointsAndSixDirectedEdges)
{
  graph::DvGraph graph;
  const auto interactions =
      planObjectInteractions(test::tJunctionScene(), 0, ObjectPhysics{0.4, 20.0}, defaultSettings());
  const InsertedInteractions inserted = insertInteractions(graph, 3, interactions, 10);
  EXPECT_EQ(inserted.waypoint_vertices.size(), 3U);
  EXPECT_EQ(inserted.edges.size(), 6U);
  EXPECT_EQ(graph.interactionEdgeCount(), 6U);
  EXPECT_EQ(inserted.plans_without_edge, 0U);
}

TEST(InteractionGraphTest, AnUnpushableEstimateRemovesTheObjectsEdges)
{
  graph::DvGraph graph;
  const InteractionSettings settings = defaultSettings();
  insertInteractions(graph, 7,
                     planObjectInteractions(test::doorwayScene(), 0, ObjectPhysics{0.4, 20.0}, settings), 0);
  ASSERT_EQ(graph.interactionEdgeCount(), 2U);
  // The force sensor found it far heavier than the vehicle can push: replanning yields no edges.
  const auto heavy = planObjectInteractions(test::doorwayScene(), 0, ObjectPhysics{0.9, 400.0}, settings);
  ASSERT_EQ(heavy.plans.size(), 2U);
  EXPECT_EQ(heavy.plans[0].plan.status, PlanStatus::TooHeavy);
  const InsertedInteractions inserted = insertInteractions(graph, 7, heavy, 2);
  EXPECT_TRUE(inserted.edges.empty());
  EXPECT_EQ(inserted.plans_without_edge, 2U);
  EXPECT_EQ(graph.interactionEdgeCount(), 0U);
}

}  // namespace
}  // namespace ifar::interaction
