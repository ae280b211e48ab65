#include "drivers/can/lcm_bridge_bus.hpp"

#include <gtest/gtest.h>

namespace ifar::can {
namespace {

using std::chrono::microseconds;

TEST(LcmBridge, ConvertsBothWays)
{
  Frame frame = makeFrame(0x18FF1234, {1, 2, 3});
  frame.flags = kFlagExtended;
  frame.timestamp_us = 77;
  const ifar::can_frame_t message = toLcm(frame);
  EXPECT_EQ(message.id, 0x18FF1234);
  EXPECT_EQ(message.flags, ifar::can_frame_t::FLAG_EXTENDED);
  EXPECT_EQ(message.dlc, 3);
  EXPECT_EQ(message.data[3], 0);
  bool valid = false;
  EXPECT_TRUE(sameContent(fromLcm(message, &valid), frame));
  EXPECT_TRUE(valid);
}

TEST(LcmBridge, FlagsBadMessages)
{
  ifar::can_frame_t message{};
  message.id = 0x123;
  message.dlc = 9;
  bool valid = true;
  EXPECT_EQ(fromLcm(message, &valid).dlc, 8);
  EXPECT_FALSE(valid);
  message.dlc = 1;
  message.id = 0x800;  // too big for a standard id
  fromLcm(message, &valid);
  EXPECT_FALSE(valid);
}

TEST(LcmBridge, TwoEndpointsTalkAndOwnFramesAreNotEchoed)
{
  lcm::LCM lcm("memq://");
  ASSERT_TRUE(lcm.good());
  LcmBridgeBus first(lcm, "CAN_TEST");
  LcmBridgeBus second(lcm, "CAN_TEST");
  ASSERT_EQ(first.send(makeFrame(0x201, {0x0F, 0x00})).status, IoStatus::kOk);
  const auto received = second.receive(microseconds(100'000));
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_EQ(received.frame.id, 0x201u);
  EXPECT_EQ(received.frame.data[0], 0x0F);
  EXPECT_EQ(first.receive(microseconds(10'000)).status, IoStatus::kTimeout);
  EXPECT_EQ(first.counters().frames_sent, 1);
  EXPECT_EQ(second.counters().frames_received, 1);

  ifar::can_frame_t bad{};
  bad.id = 0x1;
  bad.dlc = 12;
  lcm.publish("CAN_TEST", &bad);
  EXPECT_EQ(second.receive(microseconds(10'000)).status, IoStatus::kTimeout);
  EXPECT_EQ(second.counters().bad_frames, 1);

  const std::uint8_t garbage[4] = {1, 2, 3, 4};  // not a can_frame_t: counted, not printed by LCM
  lcm.publish("CAN_TEST", garbage, sizeof(garbage));
  EXPECT_EQ(second.receive(microseconds(10'000)).status, IoStatus::kTimeout);
  EXPECT_EQ(second.counters().bad_frames, 2);
}

}  // namespace
}  // namespace ifar::can
