#include <cmath>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/scenario_worlds.hpp"
#include "bench/scenarios/task_selection.hpp"
#include "sim/generators/generators.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_validation.hpp"

namespace ifar::scenarios {
namespace {

TEST(JoinOffices, TwoGeneratedOfficesMakeOne96MetresLong)
{
  const sim::World west = sim::generateOffice(3);
  const sim::World east = sim::generateOffice(4);
  const sim::WorldResult joined = joinOfficesAlongCorridor(west, east);
  ASSERT_TRUE(joined.ok()) << joined.error();
  const sim::World& world = joined.world();
  EXPECT_DOUBLE_EQ(world.bounds_min.x(), 0.0);
  EXPECT_DOUBLE_EQ(world.bounds_max.x(), 96.0);
  EXPECT_DOUBLE_EQ(world.bounds_max.y(), 24.0);
  EXPECT_EQ(world.objects.size(), west.objects.size() + east.objects.size());
  std::set<std::int64_t> ids;
  for (const sim::MovableObject& object : world.objects) {
    ids.insert(object.id);
  }
  EXPECT_EQ(ids.size(), world.objects.size());
  ASSERT_EQ(world.goals.size(), 1u);
  EXPECT_DOUBLE_EQ(world.goals.front().position.x(), east.goals.front().position.x() + 48.0);
  EXPECT_TRUE(sim::findWorldProblems(world).empty());
}

TEST(JoinOffices, TheJoinedOfficeHasTasksLongerThan80Metres)
{
  const sim::WorldResult joined = joinOfficesAlongCorridor(sim::generateOffice(5), sim::generateOffice(6));
  ASSERT_TRUE(joined.ok()) << joined.error();
  const ScenarioMaps maps = buildScenarioMaps(joined.world(), MapSettings{});
  TaskSelectionSettings settings;
  settings.count = 3;
  settings.min_optimal = 80.0;
  const std::vector<Task> tasks = selectTasks(joined.world(), maps, settings);
  ASSERT_EQ(tasks.size(), 3u);
  // The world's own task: west start room to east goal room, through the opened corridor.
  EXPECT_TRUE(tasks.front().from_world);
  for (const Task& task : tasks) {
    EXPECT_GT(task.optimal, 80.0);
  }
}

TEST(JoinOffices, RefusesWorldsThatAreNotGeneratorOffices)
{
  const sim::WorldResult joined =
      joinOfficesAlongCorridor(sim::generateRoom(1, false), sim::generateOffice(2));
  ASSERT_FALSE(joined.ok());
  EXPECT_NE(joined.error().find("not the office generator's layout"), std::string::npos) << joined.error();
}

TEST(ScenarioWorlds, QuotasAddUpToTheTaskCount)
{
  for (const ScenarioKind kind : {ScenarioKind::Room, ScenarioKind::RoomObjects, ScenarioKind::Office}) {
    const WorldSetResult set = scenarioWorlds(kind, {1, 10, "", "", 0.7});
    ASSERT_TRUE(set.ok()) << set.error;
    int quota = 0;
    for (const ScenarioWorld& world : set.worlds) {
      quota += world.task_quota;
    }
    EXPECT_EQ(quota, 10) << kindName(kind);
  }
}

TEST(ScenarioWorlds, WillowIsSkippedWithANoteWhenTheMapIsAbsent)
{
  const WorldSetResult set =
      scenarioWorlds(ScenarioKind::Willow, {1, 10, "/nonexistent/willow.yaml", "", 0.7});
  EXPECT_TRUE(set.ok());
  EXPECT_TRUE(set.worlds.empty());
  ASSERT_EQ(set.notes.size(), 1u);
  EXPECT_NE(set.notes.front().find("absent"), std::string::npos);
}

TEST(ScenarioWorlds, WillowGetsTheSameObjectsForTheSameSeed)
{
  const std::string map = std::string(IFAR_SHARED_DATA) + "/maps/willow-full.yaml";
  if (!std::ifstream(map).good()) {
    GTEST_SKIP() << map << " not found (shared data absent)";
  }
  const sim::WorldResult first = willowWithObjects(map, 4);
  const sim::WorldResult second = willowWithObjects(map, 4);
  ASSERT_TRUE(first.ok()) << first.error();
  ASSERT_TRUE(second.ok()) << second.error();
  ASSERT_EQ(first.world().objects.size(), 14u);  // 10 in doors, 4 in corridors
  for (std::size_t index = 0; index < first.world().objects.size(); ++index) {
    EXPECT_EQ(first.world().objects[index].pose.x, second.world().objects[index].pose.x);
    EXPECT_EQ(first.world().objects[index].pose.y, second.world().objects[index].pose.y);
    EXPECT_EQ(first.world().objects[index].mass_kg, second.world().objects[index].mass_kg);
  }
}

TEST(ScenarioWorlds, NoTwoSuiteSeedsShareAWorld)
{
  for (const ScenarioKind kind : {ScenarioKind::Room, ScenarioKind::Office, ScenarioKind::BlockedOffice}) {
    std::set<std::string> names;
    for (const std::uint64_t seed : {1, 2, 3}) {
      const WorldSetResult set = scenarioWorlds(kind, {seed, 4, "", "", 0.7});
      ASSERT_TRUE(set.ok()) << set.error;
      ASSERT_EQ(set.worlds.size(), 2u);
      for (const ScenarioWorld& world : set.worlds) {
        EXPECT_TRUE(names.insert(world.name).second) << world.name << " again for seed " << seed;
      }
    }
  }
  // Seed 1 keeps the worlds it always had.
  const WorldSetResult office = scenarioWorlds(ScenarioKind::Office, {1, 4, "", "", 0.7});
  ASSERT_TRUE(office.ok()) << office.error;
  EXPECT_EQ(office.worlds[0].name, "office2x-3+4");
  EXPECT_EQ(office.worlds[1].name, "office2x-5+6");
  EXPECT_EQ(scenarioWorlds(ScenarioKind::Room, {1, 4, "", "", 0.7}).worlds[1].name, "room-2");
}

TEST(ScenarioWorlds, NeverPushingInTheBlockedOfficeCostsALongWayRound)
{
  // Light boxes in the start's and the goal's room's doors and in both fire doors: the way that never
  // pushes goes round by the rooms' deep side doors, at least 1.4 times as long as the one that pushes.
  for (const std::uint64_t seed : {1, 2, 3, 4}) {
    const sim::WorldResult world = sim::generateWorld(sim::WorldKind::BlockedOffice, seed);
    ASSERT_TRUE(world.ok()) << world.error();
    // Door boxes stand square to the walls (loose boxes are turned at random): all light, four or more.
    const common::VehicleSettings vehicle;
    int door_boxes = 0;
    for (const sim::MovableObject& object : world.world().objects) {
      if (object.pose.heading == 0.0) {
        ++door_boxes;
        EXPECT_TRUE(sim::isPushable(object, vehicle)) << object.name << ", seed " << seed;
      }
    }
    EXPECT_GE(door_boxes, 4) << "seed " << seed;
    const ScenarioMaps maps = buildScenarioMaps(world.world(), MapSettings{});
    TaskSelectionSettings selection;
    selection.count = 1;
    selection.min_optimal = minimumOptimalLength(ScenarioKind::BlockedOffice);
    const std::vector<Task> tasks = selectTasks(world.world(), maps, selection);
    ASSERT_EQ(tasks.size(), 1u) << "seed " << seed;
    ASSERT_TRUE(tasks[0].from_world);
    EXPECT_GE(tasks[0].without_pushing, 1.4 * tasks[0].achievable) << "seed " << seed;
  }
}

TEST(ScenarioWorlds, TheBlockedTunnelsCratesAreLightAndAWayRoundRemains)
{
  const common::VehicleSettings vehicle;
  double achievable = 0.0;
  double without_pushing = 0.0;
  int crates = 0;
  for (const std::uint64_t seed : {1, 2, 3, 4}) {
    const sim::WorldResult world = sim::generateWorld(sim::WorldKind::BlockedTunnel, seed);
    ASSERT_TRUE(world.ok()) << world.error();
    for (const sim::MovableObject& object : world.world().objects) {
      const Eigen::AlignedBox2d box = geometry::boundingBox(sim::placedOutline(object));
      if (box.sizes().maxCoeff() > 3.0) {  // across the 4 m tunnel: a crate (loose boxes are 1 m)
        ++crates;
        EXPECT_TRUE(sim::isPushable(object, vehicle)) << object.name << ", seed " << seed;
      }
    }
    const ScenarioMaps maps = buildScenarioMaps(world.world(), MapSettings{});
    TaskSelectionSettings selection;
    selection.count = 1;
    selection.min_optimal = minimumOptimalLength(ScenarioKind::BlockedTunnel);
    const std::vector<Task> tasks = selectTasks(world.world(), maps, selection);
    ASSERT_EQ(tasks.size(), 1u) << "seed " << seed;
    // Without pushing the goal is still reachable.
    ASSERT_TRUE(std::isfinite(tasks[0].without_pushing)) << "seed " << seed;
    achievable += tasks[0].achievable;
    without_pushing += tasks[0].without_pushing;
  }
  EXPECT_GE(crates, 8);
  // Over the four worlds, never pushing costs the world's tasks at least a fifth more.
  EXPECT_GE(without_pushing, 1.2 * achievable);
}

TEST(KindNames, RoundTrip)
{
  for (const ScenarioKind kind : allKinds()) {
    EXPECT_EQ(parseKind(kindName(kind)), kind);
  }
  EXPECT_FALSE(parseKind("garage").has_value());
  EXPECT_EQ(minimumOptimalLength(ScenarioKind::Room), 15.0);
  EXPECT_EQ(minimumOptimalLength(ScenarioKind::Tunnel), 80.0);
  EXPECT_EQ(kindName(ScenarioKind::BlockedOffice), "blocked_office");
  EXPECT_EQ(minimumOptimalLength(ScenarioKind::BlockedOffice), 40.0);
}

}  // namespace
}  // namespace ifar::scenarios
