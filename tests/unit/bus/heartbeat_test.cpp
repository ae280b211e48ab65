// Heartbeats over LCM's in-process memq:// provider: one per period with the process's name, id and a
// counting sequence, OK while the loop is healthy and DEGRADED, naming the cause, after a bad message.

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <spdlog/sinks/null_sink.h>
#include <spdlog/sinks/ostream_sink.h>

#include "bus/heartbeat.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/heartbeat_t.hpp"

namespace {

using ifar::bus::LoopCounters;

TEST(Heartbeat, HealthIsOkWhileNoCounterGrows)
{
  const auto health = ifar::bus::healthBetween(LoopCounters{3, 1, 2}, LoopCounters{3, 1, 2});
  EXPECT_EQ(health.level, ifar::heartbeat_t::HEALTH_OK);
  EXPECT_EQ(health.message, "");
}

TEST(Heartbeat, HealthNamesEachCounterThatGrew)
{
  const auto health = ifar::bus::healthBetween(LoopCounters{3, 1, 2}, LoopCounters{5, 1, 3});
  EXPECT_EQ(health.level, ifar::heartbeat_t::HEALTH_DEGRADED);
  EXPECT_EQ(health.message, "2 undecodable messages, 1 failed publishes since the last beat");
}

TEST(Heartbeat, TheDaemonsOwnProblemComesFirst)
{
  const ifar::bus::LoopHealth ok{ifar::heartbeat_t::HEALTH_OK, ""};
  EXPECT_EQ(ifar::bus::withDaemonProblem(ok, "").level, ifar::heartbeat_t::HEALTH_OK);
  const auto stale = ifar::bus::withDaemonProblem(ok, "stale inputs: pose");
  EXPECT_EQ(stale.level, ifar::heartbeat_t::HEALTH_DEGRADED);
  EXPECT_EQ(stale.message, "stale inputs: pose");
  const auto both = ifar::bus::withDaemonProblem(
      ifar::bus::healthBetween(LoopCounters{0, 0, 0}, LoopCounters{1, 0, 0}), "stale inputs: pose");
  EXPECT_EQ(both.message, "stale inputs: pose; 1 undecodable messages since the last beat");
}

TEST(Heartbeat, BeatsEachPeriodAndReportsABadMessageOnce)
{
  ifar::bus::RunLoop loop("memq://", std::make_shared<spdlog::logger>(
                                         "heartbeat_test", std::make_shared<spdlog::sinks::null_sink_mt>()));
  std::vector<ifar::heartbeat_t> beats;
  loop.subscribe<ifar::heartbeat_t>(
      ifar::bus::kHeartbeatChannel,
      [&](const ifar::heartbeat_t& beat, std::int64_t) { beats.push_back(beat); });
  loop.subscribe<ifar::goal_t>("GOAL", [](const ifar::goal_t&, std::int64_t) {});
  ifar::bus::publishHeartbeats(loop, "tester", 0.02);

  const auto spinUntil = [&](std::size_t count) {
    for (int spin = 0; spin < 500 && beats.size() < count; ++spin) {
      loop.spinOnce(5);
    }
  };
  spinUntil(2);
  const std::uint8_t garbage[3] = {9, 9, 9};
  loop.lcm().publish("GOAL", garbage, sizeof(garbage));
  spinUntil(4);

  ASSERT_GE(beats.size(), 4U);
  for (std::size_t index = 0; index < beats.size(); ++index) {
    EXPECT_EQ(beats[index].process, "tester");
    EXPECT_EQ(beats[index].pid, ::getpid());
    EXPECT_EQ(beats[index].sequence, static_cast<std::int64_t>(index));
    EXPECT_GT(beats[index].utime, 1'600'000'000'000'000);  // wall clock, microseconds since 1970
  }
  EXPECT_EQ(beats[0].health, ifar::heartbeat_t::HEALTH_OK);
  EXPECT_EQ(beats[1].health, ifar::heartbeat_t::HEALTH_OK);
  // The garbage is handled before the third beat or, on a busy machine, before the fourth; exactly one
  // beat names it.
  int degraded = 0;
  for (std::size_t index = 2; index < 4; ++index) {
    if (beats[index].health == ifar::heartbeat_t::HEALTH_DEGRADED) {
      ++degraded;
      EXPECT_EQ(beats[index].message, "1 undecodable messages since the last beat");
    } else {
      EXPECT_EQ(beats[index].message, "");
    }
  }
  EXPECT_EQ(degraded, 1);
  EXPECT_EQ(loop.badMessages(), 1);
}

TEST(Heartbeat, AnotherProcessOfTheSameNameOnTheUrlDegradesEveryBeat)
{
  ifar::bus::RunLoop loop("memq://", std::make_shared<spdlog::logger>(
                                         "heartbeat_test", std::make_shared<spdlog::sinks::null_sink_mt>()));
  std::vector<ifar::heartbeat_t> beats;
  loop.subscribe<ifar::heartbeat_t>(ifar::bus::kHeartbeatChannel,
                                    [&](const ifar::heartbeat_t& beat, std::int64_t) {
                                      if (beat.pid == ::getpid()) {
                                        beats.push_back(beat);
                                      }
                                    });
  ifar::bus::publishHeartbeats(loop, "tester", 0.02);
  ifar::heartbeat_t impostor{};
  impostor.process = "tester";
  impostor.pid = ::getpid() + 1;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (beats.size() < 3 && std::chrono::steady_clock::now() < give_up) {
    loop.publish(ifar::bus::kHeartbeatChannel, impostor);
    for (int spin = 0; spin < 3; ++spin) {
      loop.spinOnce(5);
    }
  }
  ASSERT_GE(beats.size(), 3U);
  // The impostor is heard before the second beat at the latest.
  EXPECT_EQ(beats[2].health, ifar::heartbeat_t::HEALTH_DEGRADED);
  EXPECT_EQ(beats[2].message, "another tester on this LCM URL (pid " + std::to_string(::getpid() + 1) + ")");
}

TEST(Heartbeat, LoggedProblemSaysWhenAProblemStartsChangesLastsAndClears)
{
  std::ostringstream log;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(log);
  sink->set_pattern("%l %v");
  auto logger = std::make_shared<spdlog::logger>("driver", sink);
  std::vector<std::string> problems = {"",
                                       "no lidar packets on port 2368 for 1.0 s",
                                       "no lidar packets on port 2368 for 2.0 s",
                                       "no lidar packets on port 2368 for 3.0 s",
                                       "no lidar packets on port 2368 for 4.0 s",
                                       "bad packets",
                                       ""};
  std::size_t next = 0;
  const ifar::bus::DaemonProblem logged =
      ifar::bus::loggedProblem([&] { return problems[next++]; }, logger, 3);
  std::vector<std::string> reported;
  while (next < problems.size()) {
    reported.push_back(logged());
  }
  EXPECT_EQ(reported, problems);  // the heartbeat gets what the daemon says, unchanged
  EXPECT_EQ(log.str(),
            "warning no lidar packets on port 2368 for 1.0 s\n"
            "warning no lidar packets on port 2368 for 4.0 s\n"  // still so after 3 beats
            "warning bad packets\n"
            "info no longer: bad packets\n");
}

}  // namespace
