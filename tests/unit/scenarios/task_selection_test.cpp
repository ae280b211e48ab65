#include <gtest/gtest.h>

#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/task_selection.hpp"
#include "sim/generators/generators.hpp"
#include "tests/unit/scenarios/test_worlds.hpp"

namespace ifar::scenarios {
namespace {

TaskSelectionSettings roomSelection(std::uint64_t seed)
{
  TaskSelectionSettings settings;
  settings.count = 5;
  settings.seed = seed;
  settings.min_optimal = 15.0;
  return settings;
}

TEST(TaskSelection, SameSeedGivesTheSameTasks)
{
  const sim::World world = sim::generateRoom(1, true);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  const std::vector<Task> first = selectTasks(world, maps, roomSelection(7));
  const std::vector<Task> second = selectTasks(world, maps, roomSelection(7));
  ASSERT_EQ(first.size(), 5u);
  ASSERT_EQ(second.size(), first.size());
  for (std::size_t index = 0; index < first.size(); ++index) {
    EXPECT_EQ(first[index].id, "t" + std::to_string(index));
    EXPECT_EQ(first[index].start, second[index].start);
    EXPECT_EQ(first[index].goal, second[index].goal);
    EXPECT_EQ(first[index].optimal, second[index].optimal);
  }
}

TEST(TaskSelection, DifferentSeedsGiveDifferentTasks)
{
  const sim::World world = sim::generateRoom(1, false);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings first_settings = roomSelection(1);
  TaskSelectionSettings second_settings = roomSelection(2);
  first_settings.include_world_task = false;
  second_settings.include_world_task = false;
  const std::vector<Task> first = selectTasks(world, maps, first_settings);
  const std::vector<Task> second = selectTasks(world, maps, second_settings);
  ASSERT_FALSE(first.empty());
  ASSERT_FALSE(second.empty());
  EXPECT_NE(first.front().start, second.front().start);
}

TEST(TaskSelection, EveryTaskIsLongerThanTheThresholdAndStartsInFreeSpace)
{
  const sim::World world = sim::generateRoom(2, true);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings settings = roomSelection(3);
  settings.count = 8;
  const std::vector<Task> tasks = selectTasks(world, maps, settings);
  ASSERT_EQ(tasks.size(), 8u);
  for (const Task& task : tasks) {
    EXPECT_GT(task.optimal, 15.0) << task.id;
    // The optimum is never shorter than the straight line.
    EXPECT_GE(task.optimal, (task.goal - task.start).norm() - 1e-9) << task.id;
    EXPECT_FALSE(maps.exact.obstacles.isBlocked(task.start)) << task.id;
    EXPECT_GE(maps.exact.obstacles.distanceToBoundary(task.start), settings.min_clearance_m) << task.id;
    EXPECT_GE(maps.exact.obstacles.distanceToBoundary(task.goal), settings.min_clearance_m) << task.id;
  }
}

TEST(TaskSelection, TheWorldsOwnTaskComesFirstWithItsExactOptimum)
{
  const sim::World world = test::twoRoomsWithDoorBox(false);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings settings = roomSelection(1);
  settings.count = 1;
  const std::vector<Task> tasks = selectTasks(world, maps, settings);
  ASSERT_EQ(tasks.size(), 1u);
  EXPECT_TRUE(tasks.front().from_world);
  EXPECT_EQ(tasks.front().start, geometry::Point(5.0, 5.0));
  // Straight through the door: the exact optimum with the box removed is the 20 m line.
  EXPECT_NEAR(tasks.front().optimal, 20.0, 1e-9);
  EXPECT_NEAR(tasks.front().start_heading, 0.0, 1e-12);
  EXPECT_TRUE(tasks.front().reachable_with_pushing);
}

TEST(TaskSelection, AHeavyBoxInTheOnlyDoorMakesTheTaskUnreachableButKeepsIt)
{
  const sim::World world = test::twoRoomsWithDoorBox(true);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings settings = roomSelection(1);
  settings.count = 1;
  const std::vector<Task> tasks = selectTasks(world, maps, settings);
  ASSERT_EQ(tasks.size(), 1u);
  EXPECT_FALSE(tasks.front().reachable_with_pushing);
}

TEST(TaskSelection, NoTaskWhenNothingIsLongEnough)
{
  const sim::World world = test::twoRoomsWithDoorBox(false);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings settings = roomSelection(1);
  settings.min_optimal = 80.0;  // the world is 30 m long
  settings.max_attempts = 500;
  EXPECT_TRUE(selectTasks(world, maps, settings).empty());
}

TEST(TaskSelection, TheTaskWorldStartsAndEndsWhereTheTaskDoes)
{
  const sim::World world = sim::generateRoom(1, true);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings settings = roomSelection(4);
  settings.include_world_task = false;
  const std::vector<Task> tasks = selectTasks(world, maps, settings);
  ASSERT_FALSE(tasks.empty());
  const Task& task = tasks.front();
  const sim::World driven = taskWorld(world, task);
  EXPECT_EQ(driven.start.position(), task.start);
  EXPECT_DOUBLE_EQ(driven.start.heading, task.start_heading);
  ASSERT_EQ(driven.goals.size(), 1u);
  EXPECT_EQ(driven.goals.front().position, task.goal);
  EXPECT_EQ(driven.goals.front().name, "task_" + task.id);
  EXPECT_NE(world.start.position(), task.start);  // a random task: not the world's own start
  EXPECT_EQ(driven.obstacles.size(), world.obstacles.size());
  EXPECT_EQ(driven.objects.size(), world.objects.size());
}

}  // namespace
}  // namespace ifar::scenarios
