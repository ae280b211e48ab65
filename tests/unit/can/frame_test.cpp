#include "drivers/can/frame.hpp"

#include <gtest/gtest.h>

namespace ifar::can {
namespace {

TEST(CanFrame, MakeFrameCopiesAtMostEightBytes)
{
  const Frame frame = makeFrame(0x201, {1, 2, 3});
  EXPECT_EQ(frame.id, 0x201u);
  EXPECT_EQ(frame.dlc, 3);
  EXPECT_EQ(frame.data[2], 3);
  EXPECT_EQ(frame.data[3], 0);
  EXPECT_EQ(frame.payload().size(), 3u);
  const Frame long_frame = makeFrame(0x1, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  EXPECT_EQ(long_frame.dlc, 8);
}

TEST(CanFrame, LittleEndianHelpersAreExact)
{
  std::uint8_t bytes[4] = {};
  writeU32Le(bytes, 0x12345678);
  EXPECT_EQ(bytes[0], 0x78);
  EXPECT_EQ(bytes[3], 0x12);
  EXPECT_EQ(readU32Le(bytes), 0x12345678u);
  writeU16Le(bytes, 0xBEEF);
  EXPECT_EQ(bytes[0], 0xEF);
  EXPECT_EQ(bytes[1], 0xBE);
  EXPECT_EQ(readU16Le(bytes), 0xBEEF);
}

TEST(CanFrame, SameContentIgnoresTimestamp)
{
  Frame first = makeFrame(0x10, {1});
  Frame second = first;
  second.timestamp_us = 42;
  EXPECT_TRUE(sameContent(first, second));
  second.flags = kFlagExtended;
  EXPECT_FALSE(sameContent(first, second));
}

}  // namespace
}  // namespace ifar::can
