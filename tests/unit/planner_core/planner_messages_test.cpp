// The daemon's LCM conversions: sizes, ids and the polygon orientation convention on a simulated frame.

#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/polygon.hpp"
#include "planner/daemon/planner_messages.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "tests/unit/planner_core/simulated_feed.hpp"

namespace ifar::planner {
namespace {

TEST(PlannerMessages, GraphPathAndStatusCarryThePlannerResult)
{
  FrameAssembler assembler{InputSettings{}};
  const std::vector<FrameInput> frames =
      testing::feedAll(testing::recordSimulation(sim::builtinPushRoom(200.0), 0.35), assembler);
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{5, geometry::Point(6.0, 6.0)}));
  const FrameResult result = planner.processFrame(frames.front());
  const PlannerMessages messages = toMessages(planner, result, 123);

  EXPECT_EQ(messages.graph.num_vertices, static_cast<std::int32_t>(planner.graph().vertexCount()));
  EXPECT_EQ(messages.graph.num_edges, static_cast<std::int32_t>(planner.graph().visibilityEdgeCount()));
  EXPECT_EQ(messages.graph.num_polygons, static_cast<std::int32_t>(result.polygons.size()));
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    const polygon_t& polygon = messages.graph.polygons[index];
    geometry::Polygon points;
    for (int vertex = 0; vertex < polygon.num_points; ++vertex) {
      points.emplace_back(polygon.x[static_cast<std::size_t>(vertex)],
                          polygon.y[static_cast<std::size_t>(vertex)]);
    }
    const bool hole = result.polygons[index].boundary == perception::BoundaryKind::Hole;
    EXPECT_EQ(geometry::signedArea(points) < 0.0, hole) << "polygon " << index;
    const bool movable = result.polygons[index].obstacle_class == perception::ObstacleClass::Movable;
    EXPECT_EQ(polygon.kind, movable ? polygon_t::KIND_MOVABLE : polygon_t::KIND_BACKGROUND);
  }

  EXPECT_TRUE(messages.path.valid);
  EXPECT_EQ(messages.path.goal_id, 5);
  EXPECT_EQ(messages.path.utime, 123);
  ASSERT_EQ(messages.path.num_waypoints, static_cast<std::int32_t>(result.path.waypoints.size()));
  EXPECT_EQ(messages.path.waypoints.back().x, 6.0);
  EXPECT_EQ(messages.path.waypoints.front().kind, waypoint_t::KIND_FREE);
  EXPECT_EQ(messages.path.num_push_plans, 0);

  EXPECT_EQ(messages.status.state, planner_status_t::STATE_PLANNING);
  EXPECT_EQ(messages.status.frames, 1);
  EXPECT_EQ(messages.status.num_vertices, messages.graph.num_vertices);
  EXPECT_EQ(messages.status.num_polygons, messages.graph.num_polygons);
}

TEST(PlannerMessages, PoseAndDetectorConversionsSkipMalformedData)
{
  pose_t pose{};
  pose.utime = 7;
  pose.position[0] = 1.0;
  pose.orientation[0] = 0.0;
  pose.orientation[3] = 1.0;  // w x y z: half a turn about z
  const PoseSample sample = toPoseSample(pose);
  EXPECT_EQ(sample.utime, 7);
  EXPECT_DOUBLE_EQ(sample.orientation.z(), 1.0);
  EXPECT_DOUBLE_EQ(sample.orientation.w(), 0.0);

  object_polygons_t objects{};
  polygon_t good{};
  good.kind = polygon_t::KIND_MOVABLE;
  good.x = {0.0, 1.0, 1.0};
  good.y = {0.0, 0.0, 1.0};
  good.num_points = 3;
  polygon_t short_arrays = good;
  short_arrays.num_points = 4;  // claims more points than it holds
  polygon_t not_finite = good;
  not_finite.x[1] = std::numeric_limits<double>::quiet_NaN();
  objects.polygons = {good, short_arrays, not_finite};
  objects.num_polygons = 3;
  std::int64_t skipped = 0;
  const std::vector<geometry::Polygon> polygons = toPolygons(objects, skipped);
  ASSERT_EQ(polygons.size(), 1U);
  EXPECT_EQ(skipped, 2);
  EXPECT_EQ(polygons[0][2], geometry::Point(1.0, 1.0));
}

}  // namespace
}  // namespace ifar::planner
