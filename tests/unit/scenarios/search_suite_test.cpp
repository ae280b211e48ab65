#include <cmath>

#include <gtest/gtest.h>

#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/search_suite.hpp"
#include "bench/scenarios/task_selection.hpp"
#include "tests/unit/scenarios/test_worlds.hpp"

namespace ifar::scenarios {
namespace {

std::vector<ResultRow> runDoorWorld(bool heavy)
{
  const sim::World world = test::twoRoomsWithDoorBox(heavy);
  const ScenarioMaps maps = buildScenarioMaps(world, MapSettings{});
  TaskSelectionSettings selection;
  selection.count = 1;
  const std::vector<Task> tasks = selectTasks(world, maps, selection);
  SearchSuiteSettings settings;
  settings.sampling.time_cap_s = 0.2;
  return runSearchSuite(ScenarioKind::RoomObjects, world.name, maps, tasks, settings);
}

const ResultRow& rowOf(const std::vector<ResultRow>& rows, const std::string& planner)
{
  for (const ResultRow& row : rows) {
    if (row.planner == planner) {
      return row;
    }
  }
  throw std::runtime_error("no row for " + planner);
}

TEST(SearchSuite, OnlyOursCrossesADoorClosedByALightBox)
{
  const std::vector<ResultRow> rows = runDoorWorld(false);
  ASSERT_EQ(rows.size(), searchPlanners().size());
  for (const ResultRow& row : rows) {
    EXPECT_EQ(row.table, "search");
    EXPECT_EQ(row.kind, "room_objects");
    EXPECT_EQ(row.task, "t0");
    EXPECT_NEAR(row.optimal, 20.0, 1e-9);
  }
  EXPECT_FALSE(rowOf(rows, "grid_astar").success);
  EXPECT_EQ(rowOf(rows, "grid_astar").status, "no_path");
  EXPECT_FALSE(rowOf(rows, "far").success);
  EXPECT_EQ(rowOf(rows, "far").status, "no_path");
  // The sampling planners are not run where the exact search proved there is no path; the row says so.
  EXPECT_EQ(rowOf(rows, "rrt_star").status, "no_path");
  EXPECT_NE(rowOf(rows, "bit_star").reason.find("not run"), std::string::npos);
  const ResultRow& ours = rowOf(rows, "ours");
  ASSERT_TRUE(ours.success) << ours.reason;
  EXPECT_GE(ours.length, 20.0 - 1e-9);
  EXPECT_LT(ours.length, 22.0);
  EXPECT_GT(ours.graph_vertices, rowOf(rows, "far").graph_vertices);  // the topological waypoints
}

TEST(SearchSuite, AnUnreachableTaskFailsForEveryPlanner)
{
  const std::vector<ResultRow> rows = runDoorWorld(true);
  ASSERT_EQ(rows.size(), searchPlanners().size());
  for (const ResultRow& row : rows) {
    EXPECT_FALSE(row.success) << row.planner;
    EXPECT_EQ(row.status, "unreachable") << row.planner;
    EXPECT_NE(row.reason.find("unreachable even with pushing"), std::string::npos) << row.planner;
  }
}

}  // namespace
}  // namespace ifar::scenarios
