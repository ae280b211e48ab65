// namosim scenarios (../shared/data/namosim), scaled to the vehicle by the importer: the movable
// objects that block a passage get waypoints, and push plans exist that open it.

#include <filesystem>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/interaction_planner.hpp"
#include "sim/importers/namosim_svg_importer.hpp"
#include "sim/physics/convex_pieces.hpp"

namespace ifar::interaction {
namespace {

struct ScenarioOutcome {
  std::size_t objects = 0;
  std::size_t splitting_objects = 0;
  std::size_t pairs = 0;
  std::size_t found = 0;
};

/// The local layer perception would produce: walls and objects grown by the vehicle's half width.
/// Non-convex walls are grown piece by piece (overlapping convex pieces).
LocalScene inflatedScene(const sim::World& world, double inflation)
{
  LocalScene scene;
  for (const sim::StaticObstacle& obstacle : world.obstacles) {
    for (const geometry::Polygon& piece : sim::physics::convexPieces(obstacle.outline)) {
      scene.background.push_back(dilateConvex(geometry::convexHull(piece), inflation));
    }
  }
  for (const sim::MovableObject& object : world.objects) {
    geometry::Polygon outline;
    for (const geometry::Point& vertex : object.outline) {
      outline.push_back(object.pose.transform(vertex));
    }
    scene.movable.push_back(dilateConvex(geometry::convexHull(outline), inflation));
  }
  return scene;
}

ScenarioOutcome runScenario(const std::string& name)
{
  ScenarioOutcome outcome;
  const std::string path = std::string(IFAR_SHARED_DATA) + "/namosim/" + name + ".svg";
  const sim::NamosimImport imported = sim::importNamosimSvg(path, sim::NamosimImportSettings{});
  EXPECT_TRUE(imported.world.ok()) << imported.world.error();
  if (!imported.world.ok()) {
    return outcome;
  }
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  settings.search.time_budget_s = 0.5;
  const LocalScene scene = inflatedScene(imported.world.world(), settings.pusher.inflation_m);
  const ObjectPhysics physics{sim::NamosimImportSettings{}.object_ground_friction,
                              sim::NamosimImportSettings{}.object_mass_kg};
  outcome.objects = scene.movable.size();
  for (std::size_t index = 0; index < scene.movable.size(); ++index) {
    const ObjectInteractions result = planObjectInteractions(scene, index, physics, settings);
    outcome.splitting_objects += result.connectivity.splits ? 1U : 0U;
    outcome.pairs += result.plans.size();
    for (const PairPlan& pair : result.plans) {
      outcome.found += pair.plan.status == PlanStatus::Found ? 1U : 0U;
    }
  }
  return outcome;
}

struct Expected {
  std::string name;
  std::size_t objects;
  std::size_t splitting_objects;
  std::size_t pairs;
  std::size_t found;
};

void PrintTo(const Expected& expected, std::ostream* stream)
{
  *stream << expected.name;
}

class NamosimScenarioTest : public ::testing::TestWithParam<Expected> {};

TEST_P(NamosimScenarioTest, BlockingObjectsGetWaypointsAndPlans)
{
  const Expected& expected = GetParam();
  const std::string path = std::string(IFAR_SHARED_DATA) + "/namosim/" + expected.name + ".svg";
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "namosim scenario not found: " << path;
  }
  const ScenarioOutcome outcome = runScenario(expected.name);
  EXPECT_EQ(outcome.objects, expected.objects);
  EXPECT_EQ(outcome.splitting_objects, expected.splitting_objects);
  EXPECT_EQ(outcome.pairs, expected.pairs);
  EXPECT_EQ(outcome.found, expected.found);
}

// Scaled so the namosim robot is the vehicle (0.7 m):
// - minimal_stilman_2005: the box leaves 0.73 m and 0.89 m to the corridor walls, more than the vehicle's
//   width, so it splits nothing and the vehicle drives round it.
// - 1_robot_2_obstacles: two boxes plug a 1.86 m corridor one after the other; each can be pushed away
//   from the other (found) but not into it (no room beyond: exhausted).
// - obstacle_on_goal: the box stands free in the room.
INSTANTIATE_TEST_SUITE_P(Scenarios, NamosimScenarioTest,
                         ::testing::Values(Expected{"minimal_stilman_2005", 1, 0, 0, 0},
                                           Expected{"1_robot_2_obstacles", 2, 2, 4, 2},
                                           Expected{"obstacle_on_goal", 1, 0, 0, 0}),
                         [](const ::testing::TestParamInfo<Expected>& parameter) {
                           return parameter.param.name;
                         });

}  // namespace
}  // namespace ifar::interaction
