#include "tools/replay_test/log_clock_feed.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace ifar::replay_test {
namespace {

lcm_log::LogEvent eventAt(std::int64_t utime, const std::string& channel)
{
  lcm_log::LogEvent event;
  event.timestamp_us = utime;
  event.channel = channel;
  return event;
}

TEST(LogClockFeed, EachLoggedTimeGetsItsInputsThenItsTimers)
{
  std::vector<std::string> calls;
  LogClockFeed feed(
      {"POSE", "GOAL"},
      {[&calls](std::int64_t utime) { calls.push_back("time " + std::to_string(utime)); },
       [&calls](const lcm_log::LogEvent& event) { calls.push_back("deliver " + event.channel); },
       [&calls](std::int64_t utime) { calls.push_back("timers " + std::to_string(utime)); }});
  feed.add(eventAt(5, "GOAL"));
  feed.add(eventAt(5, "GLOBAL_PATH"));  // not an input: moves the clock only
  feed.add(eventAt(5, "POSE"));
  feed.add(eventAt(10, "GLOBAL_PATH"));
  feed.add(eventAt(9, "POSE"));  // out of order: taken at the current time
  feed.finish();
  const std::vector<std::string> expected{"time 5",  "deliver GOAL", "deliver POSE", "timers 5",
                                          "time 10", "deliver POSE", "timers 10"};
  EXPECT_EQ(calls, expected);
  EXPECT_EQ(feed.inputsDelivered(), 3);
}

TEST(LogClockFeed, AnEmptyLogRunsNoTimers)
{
  int timers = 0;
  LogClockFeed feed({"POSE"}, {[](std::int64_t) {}, [](const lcm_log::LogEvent&) {},
                               [&timers](std::int64_t) { ++timers; }});
  feed.finish();
  EXPECT_EQ(timers, 0);
}

}  // namespace
}  // namespace ifar::replay_test
