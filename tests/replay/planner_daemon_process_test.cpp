// ifar-planner as a real process on its own LCM URL: this test publishes simulated VELODYNE_PACKET and
// POSE messages in real time plus a GOAL, and expects GLOBAL_PATH, DV_GRAPH and PLANNER_STATUS back;
// then SIGTERM ends the daemon with exit code 0.

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "common/time.hpp"
#include "ifar/dv_graph_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "tests/unit/planner_core/simulated_feed.hpp"

extern char** environ;

namespace ifar::planner {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7731?ttl=0";

/// The daemon process; SIGTERM and reap on destruction if the test did not.
class DaemonProcess {
 public:
  explicit DaemonProcess(const std::vector<std::string>& arguments)
  {
    std::vector<char*> argv;
    for (const std::string& argument : arguments) {
      argv.push_back(const_cast<char*>(argument.c_str()));
    }
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
      pid_ = -1;
    }
  }
  ~DaemonProcess()
  {
    if (pid_ > 0) {
      stop();
    }
  }
  DaemonProcess(const DaemonProcess&) = delete;
  DaemonProcess& operator=(const DaemonProcess&) = delete;
  bool started() const { return pid_ > 0; }
  /// SIGTERM, then the exit status (-1 when it did not exit normally within 5 s).
  int stop()
  {
    kill(pid_, SIGTERM);
    for (int attempt = 0; attempt < 500; ++attempt) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    return -1;
  }

 private:
  pid_t pid_ = -1;
};

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
  DaemonProcess daemon({std::string(IFAR_BINARY_DIR) + "/bin/ifar-planner", "--config", "config/planner.yaml",
                        "--lcm-url", kLcmUrl, "--log-dir", "", "--log-level", "warn"});
  ASSERT_TRUE(daemon.started());

  // Ready when the idle status arrives (2.5 Hz while waiting).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (received.statuses == 0 && std::chrono::steady_clock::now() < deadline) {
    bus.handleTimeout(50);
  }
  ASSERT_GT(received.statuses, 0) << "no PLANNER_STATUS from the idle daemon";
  EXPECT_EQ(received.status->state, planner_status_t::STATE_IDLE);

  const std::vector<testing::FeedRecord> records =
      testing::recordSimulation(sim::builtinPushRoom(200.0), 1.2);
  const std::int64_t offset = common::nowMicroseconds() - records.front().utime;
  goal_t goal{};
  goal.goal_id = 42;
  goal.x = 6.0;
  goal.y = 6.0;
  goal.cancel = false;
  std::int64_t next_goal_utime = 0;
  for (const testing::FeedRecord& record : records) {
    const std::int64_t utime = record.utime + offset;
    while (common::nowMicroseconds() < utime) {
      bus.handleTimeout(1);
    }
    if (utime >= next_goal_utime) {  // resent, as commands on the bus are
      goal.utime = utime;
      bus.publish("GOAL", &goal);
      next_goal_utime = utime + 200'000;
    }
    if (record.kind == testing::FeedRecord::Kind::Pose) {
      pose_t pose{};
      pose.utime = utime;
      pose.position[0] = record.pose.position.x();
      pose.position[1] = record.pose.position.y();
      pose.position[2] = record.pose.position.z();
      pose.orientation[0] = record.pose.orientation.w();
      pose.orientation[1] = record.pose.orientation.x();
      pose.orientation[2] = record.pose.orientation.y();
      pose.orientation[3] = record.pose.orientation.z();
      bus.publish("POSE", &pose);
    } else {
      velodyne_packet_t packet{};
      packet.utime = utime;
      packet.port = 2368;
      packet.size = static_cast<std::int32_t>(record.payload.size());
      packet.data.assign(record.payload.begin(), record.payload.end());
      bus.publish("VELODYNE_PACKET", &packet);
    }
  }
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
  EXPECT_EQ(daemon.stop(), 0);
}

}  // namespace
}  // namespace ifar::planner
