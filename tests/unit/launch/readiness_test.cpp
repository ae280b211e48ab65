#include "tools/launch/readiness.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ifar::launch {
namespace {

constexpr std::int64_t kSecond = 1'000'000;

ProcessState running(const std::string& name, pid_t pid, std::int64_t started_us = 0)
{
  ProcessState process;
  process.name = name;
  process.pid = pid;
  process.started_us = started_us;
  return process;
}

TEST(Readiness, FirstSummaryAfterTheDelayWithEachProcessState)
{
  Readiness readiness({5.0, 3.0}, 0);
  std::vector<ProcessState> processes = {running("recorder", 100), running("velodyne", 101),
                                         running("motors", 102), running("goal", 103)};
  ProcessState crashed;
  crashed.name = "force";
  crashed.restart_pending = true;
  crashed.restarts = 2;
  crashed.last_exit = "exited with code 1";
  crashed.exit_output =
      "2026-12-01 21:13:54.396 [force-driver] [error] cannot open SocketCAN interface 'can0': no such device";
  processes.insert(processes.begin() + 2, crashed);
  readiness.onHeartbeat({100, "recorder", 0, ""}, 4 * kSecond);
  readiness.onHeartbeat({101, "velodyne-driver", 1, "no lidar packets from 192.168.1.201:2368 for 3.0 s"},
                        4 * kSecond);
  readiness.onHeartbeat({102, "motor-driver", 2, "drive 1 heartbeat lost"}, 4 * kSecond);
  EXPECT_FALSE(readiness.report(processes, 4 * kSecond).has_value());  // too early
  const auto lines = readiness.report(processes, 5 * kSecond);
  ASSERT_TRUE(lines.has_value());
  const std::vector<std::string> expected = {
      "readiness after 5 s: 1 of 5 ready",
      "  recorder  ready",
      "  velodyne  not ready: no lidar packets from 192.168.1.201:2368 for 3.0 s",
      "  force     restarting: exited with code 1: cannot open SocketCAN interface 'can0': no such device",
      "  motors    error: drive 1 heartbeat lost",
      "  goal      up, no heartbeat"};
  EXPECT_EQ(*lines, expected);
}

TEST(Readiness, ReportsAgainOnlyWhenALineChangesTheClockAside)
{
  Readiness readiness({1.0, 3.0}, 0);
  const std::vector<ProcessState> processes = {running("velodyne", 101)};
  readiness.onHeartbeat({101, "velodyne-driver", 1, "no lidar packets on port 2368 for 1.0 s"}, kSecond);
  ASSERT_TRUE(readiness.report(processes, kSecond).has_value());
  readiness.onHeartbeat({101, "velodyne-driver", 1, "no lidar packets on port 2368 for 2.0 s"}, 2 * kSecond);
  EXPECT_FALSE(readiness.report(processes, 2 * kSecond).has_value());
  readiness.onHeartbeat({101, "velodyne-driver", 0, ""}, 3 * kSecond);
  const auto ready = readiness.report(processes, 3 * kSecond);
  ASSERT_TRUE(ready.has_value());
  EXPECT_EQ(ready->front(), "readiness after 3 s: 1 of 1 ready");
  EXPECT_EQ(ready->back(), "  velodyne  ready");
  // Silent for longer than the heartbeat timeout: a process that hangs.
  const auto hung = readiness.report(processes, 7 * kSecond);
  ASSERT_TRUE(hung.has_value());
  EXPECT_EQ(hung->back(), "  velodyne  no heartbeat for 4 s");
  EXPECT_FALSE(readiness.report(processes, 9 * kSecond).has_value());
}

TEST(Readiness, ABeatFromBeforeARestartDoesNotCount)
{
  Readiness readiness({1.0, 3.0}, 0);
  readiness.onHeartbeat({101, "planner", 0, ""}, kSecond);
  ProcessState restarted = running("planner", 101, 2 * kSecond);
  restarted.restarts = 1;
  restarted.last_exit = "killed by signal 9 (Killed)";
  const auto lines = readiness.report({restarted}, 3 * kSecond);
  ASSERT_TRUE(lines.has_value());
  EXPECT_EQ(lines->back(), "  planner  restarting: killed by signal 9 (Killed)");
  ProcessState ended;
  ended.name = "planner";
  ended.done = true;
  ended.last_exit = "exited with code 0";
  EXPECT_EQ(readiness.summary({ended}, 3 * kSecond).back(), "  planner  ended: exited with code 0");
}

TEST(Readiness, ReadyOnlyOnARecentOkBeatAndWaitingOnesSayForWhat)
{
  Readiness readiness({1.0, 3.0}, 0);
  const ProcessState recorder = running("recorder", 100, kSecond);
  EXPECT_FALSE(readiness.ready(recorder, kSecond));
  readiness.onHeartbeat({100, "recorder", 1, "waiting for lcm-logger to open its log file"}, kSecond);
  EXPECT_FALSE(readiness.ready(recorder, kSecond));
  readiness.onHeartbeat({100, "recorder", 0, ""}, 2 * kSecond);
  EXPECT_TRUE(readiness.ready(recorder, 2 * kSecond));
  EXPECT_FALSE(readiness.ready(recorder, 6 * kSecond));  // its beats stopped
  ProcessState planner;
  planner.name = "planner";
  planner.waiting_for = "recorder";
  EXPECT_FALSE(readiness.ready(planner, 2 * kSecond));
  const std::vector<std::string> lines = readiness.summary({recorder, planner}, 2 * kSecond);
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[2], "  planner   waiting for recorder");
}

TEST(Readiness, NoSummaryWhenTurnedOff)
{
  Readiness readiness({0.0, 3.0}, 0);
  EXPECT_FALSE(readiness.report({running("planner", 1)}, 100 * kSecond).has_value());
}

}  // namespace
}  // namespace ifar::launch
