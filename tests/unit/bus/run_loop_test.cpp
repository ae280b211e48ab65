// The run loop over LCM's in-process memq:// provider: typed delivery, handlers that throw (anything) are
// counted and the loop goes on, undecodable messages are counted, timers fire.

#include <gtest/gtest.h>

#include <stdexcept>

#include <spdlog/sinks/null_sink.h>

#include "common/bus/run_loop.hpp"
#include "ifar/goal_t.hpp"

namespace {

std::shared_ptr<spdlog::logger> quietLogger()
{
  return std::make_shared<spdlog::logger>("run_loop_test", std::make_shared<spdlog::sinks::null_sink_mt>());
}

ifar::goal_t goal(std::int64_t id)
{
  ifar::goal_t message{};
  message.goal_id = id;
  message.x = 1.5;
  message.y = -2.0;
  return message;
}

TEST(RunLoop, DeliversTypedMessagesAndSurvivesThrowingHandlers)
{
  ifar::bus::RunLoop loop("memq://", quietLogger());
  std::vector<std::int64_t> received;
  loop.subscribe<ifar::goal_t>("GOAL", [&](const ifar::goal_t& message, std::int64_t /*receive*/) {
    received.push_back(message.goal_id);
    if (message.goal_id == 2) {
      throw std::runtime_error("bad goal");
    }
    if (message.goal_id == 3) {
      throw 42;  // not a std::exception: must not unwind into LCM's C code either
    }
  });
  for (std::int64_t id = 1; id <= 4; ++id) {
    loop.publish("GOAL", goal(id));
  }
  for (int spin = 0; spin < 10 && received.size() < 4; ++spin) {
    loop.spinOnce(10);
  }
  EXPECT_EQ(received, (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(loop.handlerErrors(), 2);
  EXPECT_EQ(loop.badMessages(), 0);
}

TEST(RunLoop, CountsMessagesThatDoNotDecode)
{
  ifar::bus::RunLoop loop("memq://", quietLogger());
  int delivered = 0;
  loop.subscribe<ifar::goal_t>("GOAL", [&](const ifar::goal_t&, std::int64_t) { ++delivered; });
  const std::uint8_t garbage[5] = {1, 2, 3, 4, 5};
  loop.lcm().publish("GOAL", garbage, sizeof(garbage));
  loop.publish("GOAL", goal(7));
  for (int spin = 0; spin < 10 && delivered == 0; ++spin) {
    loop.spinOnce(10);
  }
  loop.spinOnce(10);
  EXPECT_EQ(delivered, 1);
  EXPECT_EQ(loop.badMessages(), 1);
}

TEST(RunLoop, TimersFireAndStopEndsRun)
{
  ifar::bus::RunLoop loop("memq://", quietLogger());
  int ticks = 0;
  loop.every(0.005, [&] {
    if (++ticks == 3) {
      loop.stop();
    }
  });
  EXPECT_EQ(loop.run(), 0);
  EXPECT_EQ(ticks, 3);
}

}  // namespace
