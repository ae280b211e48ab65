// ifar-planner as a process (own LCM URL, udpm port 7737) on the demo room: the path pushes the doorway
// box and carries its push plan; GLOBAL_PATH is resent at daemon.path_resend_hz between graph updates;
// an AFFORDANCE calling the box unpushable gives a path without pushes at once; bad AFFORDANCE messages
// are counted.

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "ifar/affordance_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "sim/world/world_file.hpp"
#include "testing/child_process.hpp"
#include "testing/simulated_feed.hpp"
#include "tests/replay/feed_publisher.hpp"

namespace ifar::planner {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7737?ttl=0";

struct Received {
  std::vector<path_t> paths;
  std::optional<planner_status_t> status;
  void onPath(const lcm::ReceiveBuffer*, const std::string&, const path_t* message)
  {
    paths.push_back(*message);
  }
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const planner_status_t* message)
  {
    status = *message;
  }
};

bool hasPush(const path_t& path)
{
  return path.valid && path.num_push_plans > 0;
}

TEST(PlannerDaemonInteraction, PushPathResendAndAffordance)
{
  lcm::LCM bus(kLcmUrl);
  if (!bus.good()) {
    GTEST_SKIP() << "LCM cannot start on " << kLcmUrl << " (no multicast route on this machine?)";
  }
  const sim::WorldResult world =
      sim::loadWorldFile(std::string(IFAR_SOURCE_DIR) + "/config/worlds/demo_room.yaml");
  ASSERT_TRUE(world.ok()) << world.error();
  Received received;
  bus.subscribe("GLOBAL_PATH", &Received::onPath, &received);
  bus.subscribe("PLANNER_STATUS", &Received::onStatus, &received);

  ASSERT_EQ(chdir(IFAR_SOURCE_DIR), 0);  // the default config paths are relative to the repository
  test_support::ChildProcess daemon({std::string(IFAR_BINARY_DIR) + "/bin/ifar-planner", "--config",
                                     "config/planner.yaml", "--lcm-url", kLcmUrl, "--log-dir", "",
                                     "--log-level", "error"});
  ASSERT_TRUE(daemon.started());
  const auto ready = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!received.status && std::chrono::steady_clock::now() < ready) {
    bus.handleTimeout(50);
  }
  ASSERT_TRUE(received.status) << "no PLANNER_STATUS from the idle daemon";

  goal_t goal{};
  goal.goal_id = 8;
  goal.x = 8.0;
  goal.y = 26.0;
  replay_testing::publishInRealTime(bus, test_support::recordSimulation(world.world(), 1.0), goal);
  const auto answer = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while ((received.paths.empty() || !hasPush(received.paths.back())) &&
         std::chrono::steady_clock::now() < answer) {
    bus.handleTimeout(50);
  }
  ASSERT_FALSE(received.paths.empty()) << "no GLOBAL_PATH";
  const path_t pushed = received.paths.back();
  ASSERT_TRUE(hasPush(pushed));
  ASSERT_EQ(pushed.num_push_plans, 1);
  const std::int64_t box = pushed.push_plans.front().object_id;
  EXPECT_GT(box, 0);
  EXPECT_GT(pushed.push_plans.front().num_controls, 0);

  // Input stopped: once the last revolution is through, no graph updates, yet the same path keeps coming
  // with fresh stamps at about daemon.path_resend_hz (20 Hz in config/planner.yaml).
  const auto settle = std::chrono::steady_clock::now() + std::chrono::milliseconds(800);
  while (std::chrono::steady_clock::now() < settle) {
    bus.handleTimeout(20);
  }
  received.paths.clear();
  const auto quiet_start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() < quiet_start + std::chrono::milliseconds(1000)) {
    bus.handleTimeout(20);
  }
  ASSERT_GE(received.paths.size(), 12U);
  EXPECT_LE(received.paths.size(), 26U);
  for (std::size_t index = 1; index < received.paths.size(); ++index) {
    EXPECT_EQ(received.paths[index].sequence, received.paths.front().sequence);
    EXPECT_EQ(received.paths[index].num_push_plans, 1);
    EXPECT_GT(received.paths[index].utime, received.paths[index - 1].utime);
    EXPECT_LT(received.paths[index].utime - received.paths[index - 1].utime, 100'000);
  }

  // Bad estimates are counted, a good one replans at once.
  affordance_t bad{};
  bad.object_id = box;
  bad.pushable = false;
  bad.push_force_n = std::numeric_limits<double>::quiet_NaN();
  bus.publish("AFFORDANCE", &bad);
  affordance_t unknown{};
  unknown.object_id = 777;
  unknown.pushable = false;
  bus.publish("AFFORDANCE", &unknown);
  const std::int64_t bad_before = received.status->bad_inputs;
  const auto counted = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (received.status->bad_inputs < bad_before + 2 && std::chrono::steady_clock::now() < counted) {
    bus.handleTimeout(20);
  }
  EXPECT_GE(received.status->bad_inputs, bad_before + 2);
  ASSERT_FALSE(received.paths.empty());
  EXPECT_TRUE(hasPush(received.paths.back()));

  affordance_t unpushable{};
  unpushable.object_id = box;
  unpushable.pushable = false;
  received.paths.clear();
  bus.publish("AFFORDANCE", &unpushable);
  const auto sent = std::chrono::steady_clock::now();
  std::optional<std::chrono::steady_clock::time_point> replanned;
  while (!replanned && std::chrono::steady_clock::now() < sent + std::chrono::seconds(2)) {
    bus.handleTimeout(10);
    for (const path_t& path : received.paths) {
      if (path.valid && path.num_push_plans == 0 && !replanned) {
        replanned = std::chrono::steady_clock::now();
      }
    }
  }
  ASSERT_TRUE(replanned) << "no path without the push after AFFORDANCE";
  EXPECT_LT(std::chrono::duration<double>(*replanned - sent).count(), 0.5);  // no frames come any more
  EXPECT_EQ(daemon.stop(SIGTERM), 0);
}

}  // namespace
}  // namespace ifar::planner
