// Determinism of the planner pipeline: a log of simulated VLP-16 packets and poses (the vehicle driving
// a curve past a box), replayed twice through FrameAssembler and Planner, gives the same global graph
// and the same path after every frame, bit for bit.

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"
#include "planner/graph/graph_file.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

struct FrameOutcome {
  std::string graph;  // serialized global graph (17 significant digits: exact)
  std::vector<geometry::Point> path;
  bool path_valid = false;
  PlannerState state = PlannerState::Idle;
  std::int32_t flags = 0;
  std::int64_t polygons = 0;
  StageTimings timings;
};

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

std::vector<FrameOutcome> replay(const std::vector<test_support::FeedRecord>& log)
{
  FrameAssembler assembler{InputSettings{}};
  Planner planner{PlannerSettings{}};
  planner.setGoal(Goal{1, geometry::Point(9.0, 8.0)});
  std::vector<FrameOutcome> outcomes;
  for (const FrameInput& frame : test_support::feedAll(log, assembler)) {
    const FrameResult result = planner.processFrame(frame);
    FrameOutcome outcome;
    outcome.graph = graph::serializeGraph(planner.graph());
    for (const auto& waypoint : result.path.waypoints) {
      outcome.path.push_back(waypoint.position);
    }
    outcome.path_valid = result.path.valid;
    outcome.state = result.status.state;
    outcome.flags = result.status.flags;
    outcome.polygons = result.status.polygons;
    outcome.timings = result.status.timings;
    outcomes.push_back(std::move(outcome));
  }
  return outcomes;
}

TEST(PlannerReplay, SameRecordedPacketsGiveTheSameGraphAndPath)
{
  // 2 s at 0.4 m/s turning left at 0.25 rad/s: about 20 revolutions from a moving sensor.
  const std::vector<test_support::FeedRecord> log =
      test_support::recordSimulation(sim::builtinPushRoom(200.0), 2.0, 0.4, 0.25);
  const std::vector<FrameOutcome> first = replay(log);
  const std::vector<FrameOutcome> second = replay(log);

  ASSERT_GE(first.size(), 15U);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t index = 0; index < first.size(); ++index) {
    SCOPED_TRACE("frame " + std::to_string(index));
    EXPECT_EQ(first[index].graph, second[index].graph);
    EXPECT_EQ(first[index].path_valid, second[index].path_valid);
    ASSERT_EQ(first[index].path.size(), second[index].path.size());
    for (std::size_t point = 0; point < first[index].path.size(); ++point) {
      EXPECT_EQ(first[index].path[point].x(), second[index].path[point].x());
      EXPECT_EQ(first[index].path[point].y(), second[index].path[point].y());
    }
    EXPECT_EQ(first[index].state, second[index].state);
    EXPECT_EQ(first[index].flags, second[index].flags);
    EXPECT_EQ(first[index].polygons, second[index].polygons);
  }
  // Informative only (speed targets are benchmarks): medians over the replay's frames.
  std::vector<double> perception;
  std::vector<double> local_graph;
  std::vector<double> merge;
  std::vector<double> search;
  std::vector<double> total;
  for (const FrameOutcome& outcome : first) {
    perception.push_back(outcome.timings.perception_ms);
    local_graph.push_back(outcome.timings.local_graph_ms);
    merge.push_back(outcome.timings.merge_ms);
    search.push_back(outcome.timings.search_ms);
    total.push_back(outcome.timings.total_ms);
  }
  std::cout << "median ms per frame: perception " << median(perception) << ", local graph "
            << median(local_graph) << ", merge " << median(merge) << ", search " << median(search)
            << ", total " << median(total) << " (" << first.size() << " frames)\n";

  // The replay did real work: the merged graph grew and a path to the goal exists at the end.
  EXPECT_EQ(first.back().state, PlannerState::Planning);
  EXPECT_TRUE(first.back().path_valid);
  EXPECT_GT(first.back().graph.size(), first.front().graph.size() / 2);
  EXPECT_NE(first.back().graph.find("\nv "), std::string::npos);
}

}  // namespace
}  // namespace ifar::planner
