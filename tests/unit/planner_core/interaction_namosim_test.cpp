// namosim scenarios (../shared/data/namosim) through the whole planner, fed the simulator's VLP-16
// packets; the push plan the path carries is then executed open loop in a fresh simulator whose vehicle
// starts at the plan's contact pose, and must open the passage between the two topological waypoints.

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "sim/importers/namosim_svg_importer.hpp"
#include "sim/simulator/simulator.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

std::string scenarioPath(const std::string& name)
{
  return std::string(IFAR_SHARED_DATA) + "/namosim/" + name + ".svg";
}

sim::World importScenario(const std::string& name)
{
  const sim::NamosimImport imported = sim::importNamosimSvg(scenarioPath(name), sim::NamosimImportSettings{});
  EXPECT_TRUE(imported.world.ok()) << imported.world.error();
  return imported.world.ok() ? imported.world.world() : sim::World{};
}

/// The planner after a few frames of the vehicle standing at the world's start.
FrameResult planFromStart(const sim::World& world, const geometry::Point& goal, Planner& planner)
{
  FrameAssembler assembler{InputSettings{}};
  const std::vector<FrameInput> frames =
      test_support::feedAll(test_support::recordSimulation(world, 0.35), assembler);
  EXPECT_GE(frames.size(), 2U);
  EXPECT_TRUE(planner.setGoal(Goal{1, goal}));
  FrameResult result;
  for (const FrameInput& frame : frames) {
    result = planner.processFrame(frame);
  }
  return result;
}

/// World pose of the object that started nearest `near`, after running the push plan's controls open loop
/// from its contact pose. Contact switches are driven as their straight travel (none in these plans).
geometry::Polygon executePush(sim::World world, const PathPush& push, const geometry::Point& near)
{
  world.start = push.plan.contact_pose;
  sim::SimulatorSettings settings;
  settings.lidar_enabled = false;
  sim::Simulator simulator(world, common::VehicleSettings{}, settings);
  std::size_t pushed = 0;
  for (std::size_t index = 1; index < world.objects.size(); ++index) {
    if ((world.objects[index].pose.position() - near).norm() <
        (world.objects[pushed].pose.position() - near).norm()) {
      pushed = index;
    }
  }
  sim::StepOutput output = simulator.step(0.01);
  for (const interaction::PushControl& control : push.plan.controls) {
    simulator.setVelocityCommand(control.linear_mps, control.angular_radps);
    output = simulator.step(control.duration_s);
  }
  simulator.setVelocityCommand(0.0, 0.0);
  output = simulator.step(0.5);
  geometry::Polygon outline;
  for (const geometry::Point& vertex : world.objects[pushed].outline) {
    outline.push_back(output.objects[pushed].pose.transform(vertex));
  }
  return outline;
}

TEST(InteractionNamosim, PushedBoxOpensTheCorridorOfOneRobotTwoObstacles)
{
  if (!std::filesystem::exists(scenarioPath("1_robot_2_obstacles"))) {
    GTEST_SKIP() << "namosim scenario not found: " << scenarioPath("1_robot_2_obstacles");
  }
  sim::World world = importScenario("1_robot_2_obstacles");
  ASSERT_EQ(world.objects.size(), 2U);
  ASSERT_EQ(world.goals.size(), 1U);
  // Two boxes plug the corridor one after the other. From the scenario's own start the map's open sides
  // (no walls left and right) make driving round cheaper than pushing box 1 into box 2, so the vehicle is
  // put between the boxes facing box 2: only pushing box 2 out of the corridor leads to the goal.
  const geometry::Point first_box = world.objects[0].pose.position();
  const geometry::Point second_box = world.objects[1].pose.position();
  world.start =
      geometry::Pose2{0.5 * (first_box.x() + second_box.x()), 0.5 * (first_box.y() + second_box.y()), 0.0};

  Planner planner{PlannerSettings{}};
  const FrameResult result = planFromStart(world, world.goals.front().position, planner);
  ASSERT_TRUE(result.path.valid) << result.status.message;
  ASSERT_EQ(result.path.pushes.size(), 1U);
  const PathPush& push = result.path.pushes.front();
  EXPECT_GT(push.object_id, 0);
  EXPECT_EQ(push.to_waypoint, push.from_waypoint + 1);
  EXPECT_EQ(push.plan.status, interaction::PlanStatus::Found);
  ASSERT_FALSE(push.plan.controls.empty());
  // The pushed object is the second box (the tracked outline lies on it).
  bool on_second_box = false;
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    if (result.polygon_ids[index] == push.object_id) {
      on_second_box = (geometry::centroid(result.polygons[index].vertices) - second_box).norm() < 0.5;
    }
  }
  EXPECT_TRUE(on_second_box);
  for (const interaction::PushControl& control : push.plan.controls) {
    ASSERT_NE(control.kind, interaction::ControlKind::ContactSwitch) << "open-loop check expects pushes only";
  }

  // Open loop in the simulator: afterwards the straight drive between the waypoints is clear of the box
  // grown by the vehicle's half width.
  const geometry::Point from = result.path.waypoints[push.from_waypoint].position;
  const geometry::Point to = result.path.waypoints[push.to_waypoint].position;
  const geometry::Polygon before = [&] {
    geometry::Polygon outline;
    for (const geometry::Point& vertex : world.objects[1].outline) {
      outline.push_back(world.objects[1].pose.transform(vertex));
    }
    return outline;
  }();
  const double inflation = common::VehicleSettings{}.width_m / 2.0;
  EXPECT_LT(interaction::segmentPolygonDistance(geometry::Segment{from, to}, before), inflation)
      << "the box blocks the passage before the push";
  const geometry::Polygon after = executePush(world, push, second_box);
  EXPECT_GE(interaction::segmentPolygonDistance(geometry::Segment{from, to}, after), inflation)
      << "the pushed box still blocks the passage";
}

/// Scenarios whose box leaves room to pass (scaled to the vehicle): the planner drives round, no push.
class InteractionNamosimFree : public ::testing::TestWithParam<std::string> {};

TEST_P(InteractionNamosimFree, PathWithoutPush)
{
  if (!std::filesystem::exists(scenarioPath(GetParam()))) {
    GTEST_SKIP() << "namosim scenario not found: " << scenarioPath(GetParam());
  }
  const sim::World world = importScenario(GetParam());
  ASSERT_FALSE(world.goals.empty());
  Planner planner{PlannerSettings{}};
  const FrameResult result = planFromStart(world, world.goals.front().position, planner);
  EXPECT_TRUE(result.path.valid) << result.status.message;
  EXPECT_TRUE(result.path.pushes.empty());
  EXPECT_EQ(result.status.interaction_edges, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, InteractionNamosimFree,
                         ::testing::Values("minimal_stilman_2005", "obstacle_on_goal"));

}  // namespace
}  // namespace ifar::planner
