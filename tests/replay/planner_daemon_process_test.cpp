// ifar-planner as a real process on its own LCM URL: this test publishes simulated VELODYNE_PACKET and
// POSE messages in real time plus a GOAL, and expects GLOBAL_PATH, DV_GRAPH and PLANNER_STATUS back;
// then SIGTERM ends the daemon with exit code 0.

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "ifar/dv_graph_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "testing/child_process.hpp"
#include "testing/simulated_feed.hpp"
#include "tests/replay/feed_publisher.hpp"

namespace ifar::planner {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7731?ttl=0";

struct Received {
  std::optional<path_t> path;
  std::optional<dv_graph_t> graph;
  std::optional<planner_status_t> status;
  int statuses = 0;
  void onPath(const lcm::ReceiveBuffer*, const std::string&, const path_t* message) { path = *message; }
  void onGraph(const lcm::ReceiveBuffer*, const std::string&, const dv_graph_t* message) { graph = *message; }
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const planner_status_t* message)
  {
    status = *message;
    ++statuses;
  }
};

TEST(PlannerDaemonProcess, PublishesPathGraphAndStatusForSimulatedInput)
{
  lcm::LCM bus(kLcmUrl);
  if (!bus.good()) {
    GTEST_SKIP() << "LCM cannot start on " << kLcmUrl << " (no multicast route on this machine?)";
  }
  Received received;
  bus.subscribe("GLOBAL_PATH", &Received::onPath, &received);
  bus.subscribe("DV_GRAPH", &Received::onGraph, &received);
  bus.subscribe("PLANNER_STATUS", &Received::onStatus, &received);

  const std::string source = IFAR_SOURCE_DIR;
  ASSERT_EQ(chdir(source.c_str()), 0);  // the default config paths are relative to the repository
  test_support::ChildProcess daemon({std::string(IFAR_BINARY_DIR) + "/bin/ifar-planner", "--config",
                                     "config/planner.yaml", "--lcm-url", kLcmUrl, "--log-dir", "",
                                     "--log-level", "warn"});
  ASSERT_TRUE(daemon.started());

  // Ready when the idle status arrives (2.5 Hz while waiting).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (received.statuses == 0 && std::chrono::steady_clock::now() < deadline) {
    bus.handleTimeout(50);
  }
  ASSERT_GT(received.statuses, 0) << "no PLANNER_STATUS from the idle daemon";
  EXPECT_EQ(received.status->state, planner_status_t::STATE_IDLE);

  const std::vector<test_support::FeedRecord> records =
      test_support::recordSimulation(sim::builtinPushRoom(200.0), 1.2);
  goal_t goal{};
  goal.goal_id = 42;
  goal.x = 6.0;
  goal.y = 6.0;
  goal.cancel = false;
  replay_testing::publishInRealTime(bus, records, goal);
  const auto answer_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (!(received.path && received.path->valid) && std::chrono::steady_clock::now() < answer_deadline) {
    bus.handleTimeout(50);
  }

  ASSERT_TRUE(received.path.has_value()) << "no GLOBAL_PATH";
  EXPECT_TRUE(received.path->valid);
  EXPECT_EQ(received.path->goal_id, 42);
  ASSERT_GE(received.path->num_waypoints, 3);  // around the box
  EXPECT_NEAR(received.path->waypoints.back().x, 6.0, 1e-9);
  EXPECT_NEAR(received.path->waypoints.back().y, 6.0, 1e-9);
  ASSERT_TRUE(received.graph.has_value()) << "no DV_GRAPH";
  EXPECT_GT(received.graph->num_vertices, 0);
  EXPECT_GT(received.graph->num_polygons, 0);
  ASSERT_TRUE(received.status.has_value());
  EXPECT_EQ(received.status->state, planner_status_t::STATE_PLANNING) << received.status->message;
  EXPECT_GE(received.status->frames, 1);
  EXPECT_GT(received.status->total_ms, 0.0F);
  EXPECT_EQ(daemon.stop(SIGTERM), 0);
}

}  // namespace
}  // namespace ifar::planner
