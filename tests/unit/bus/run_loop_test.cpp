// The run loop over LCM's in-process memq:// provider: typed delivery, handlers that throw (anything) are
// counted and the loop goes on, undecodable messages are counted, timers fire; over udpm:// a backlog is
// kept.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

#include <spdlog/sinks/null_sink.h>

#include "bus/run_loop.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/velodyne_packet_t.hpp"

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

// LCM's generated decode resizes an array to the length the message claims before reading it: a negative
// length throws std::length_error, which used to end the daemon.
TEST(RunLoop, CountsMessagesWhoseDecodeThrows)
{
  ifar::bus::RunLoop loop("memq://", quietLogger());
  std::vector<std::int32_t> sizes;
  loop.subscribe<ifar::velodyne_packet_t>(
      "VELODYNE_PACKET",
      [&](const ifar::velodyne_packet_t& packet, std::int64_t) { sizes.push_back(packet.size); });
  ifar::velodyne_packet_t packet{};
  packet.size = 3;
  packet.data = {7, 8, 9};
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(packet.getEncodedSize()));
  ASSERT_EQ(packet.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  std::vector<std::uint8_t> negative_size = bytes;
  constexpr std::size_t kSizeOffset = 8 + 8 + 4 + 4;  // fingerprint, utime, device time, port
  std::fill_n(negative_size.begin() + kSizeOffset, 4, std::uint8_t{0xff});
  loop.lcm().publish("VELODYNE_PACKET", negative_size.data(), static_cast<unsigned>(negative_size.size()));
  loop.lcm().publish("VELODYNE_PACKET", bytes.data(), static_cast<unsigned>(bytes.size()));
  for (int spin = 0; spin < 10 && sizes.empty(); ++spin) {
    loop.spinOnce(10);
  }
  loop.spinOnce(10);
  EXPECT_EQ(sizes, (std::vector<std::int32_t>{3}));
  EXPECT_EQ(loop.badMessages(), 1);
  EXPECT_EQ(loop.handlerErrors(), 0);
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

TEST(RunLoop, KeepsEveryMessageThatArrivesWhileTheLoopIsBusy)
{
  // LCM alone keeps 30 waiting messages per subscription and drops the rest (40 ms of VLP-16 packets).
  // memq:// has no such limit, so this runs over UDP multicast, kept on the host.
  const std::string url = "udpm://239.255.76.67:7751?ttl=0";
  {
    lcm::LCM probe(url);
    if (!probe.good()) {
      GTEST_SKIP() << "LCM cannot start on " << url << " (no multicast route on this machine?)";
    }
  }
  ifar::bus::RunLoop loop(url, quietLogger());
  std::vector<std::int64_t> received;
  loop.subscribe<ifar::goal_t>("RUN_LOOP_TEST_GOAL", [&](const ifar::goal_t& message, std::int64_t) {
    received.push_back(message.goal_id);
  });
  // 100 small messages fit the socket's default receive buffer even if LCM's receive thread never ran.
  constexpr std::int64_t kWaiting = 100;
  for (std::int64_t id = 1; id <= kWaiting; ++id) {
    loop.publish("RUN_LOOP_TEST_GOAL", goal(id));
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // every message has arrived and waits
  for (std::int64_t spin = 0; spin < 4 * kWaiting && static_cast<std::int64_t>(received.size()) < kWaiting;
       ++spin) {
    loop.spinOnce(10);
  }
  ASSERT_EQ(static_cast<std::int64_t>(received.size()), kWaiting);
  EXPECT_EQ(received.front(), 1);
  EXPECT_EQ(received.back(), kWaiting);
}

}  // namespace
