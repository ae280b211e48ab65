// The planner node refuses goals no vehicle can drive to, and keeps the one it has.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include "planner/node/planner_node.hpp"

namespace ifar::planner {
namespace {

goal_t goalAt(std::int64_t id, double x, double y)
{
  goal_t goal{};
  goal.goal_id = id;
  goal.x = x;
  goal.y = y;
  return goal;
}

TEST(PlannerNodeGoals, NonFiniteOrAbsurdGoalsAreRefusedAndCounted)
{
  PlannerNode node(NodeSettings{},
                   std::make_shared<spdlog::logger>("planner_node_goal_test",
                                                    std::make_shared<spdlog::sinks::null_sink_mt>()),
                   0);
  EXPECT_TRUE(node.onGoal(goalAt(1, 8.0, 26.0), 0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(node.onGoal(goalAt(2, nan, 1.0), 0));
  EXPECT_FALSE(node.onGoal(goalAt(3, 1.0, -infinity), 0));
  EXPECT_FALSE(node.onGoal(goalAt(4, 1e300, 0.0), 0));
  EXPECT_FALSE(node.onGoal(goalAt(5, 0.0, -1.0000001e6), 0));
  EXPECT_EQ(node.refusedInputs(), 4);
  // The goal in force is still the first: resending it is no change.
  EXPECT_FALSE(node.onGoal(goalAt(1, 8.0, 26.0), 0));
  // At the limit is a goal.
  EXPECT_TRUE(node.onGoal(goalAt(6, 1e6, -1e6), 0));
  EXPECT_EQ(node.refusedInputs(), 4);
}

}  // namespace
}  // namespace ifar::planner
