#include "drivers/force_sensor/force_frame.hpp"

#include <gtest/gtest.h>

namespace ifar::force_sensor {
namespace {

TEST(ForceFrame, EncodesExactBytes)
{
  // 123.456 N = 123456 mN = 0x0001E240, little-endian; overload; counter 7; checksum 0x12B & 0xFF.
  const can::Frame frame = encodeForceFrame(ForceReading{123.456, 7, true, false});
  EXPECT_EQ(frame.id, 0x190u);
  EXPECT_EQ(frame.flags, 0);
  ASSERT_EQ(frame.dlc, 8);
  const std::array<std::uint8_t, 8> expected = {0x40, 0xE2, 0x01, 0x00, 0x01, 0x07, 0x00, 0x2B};
  EXPECT_EQ(frame.data, expected);
}

TEST(ForceFrame, DecodesWhatItEncodesIncludingNegativeForce)
{
  const auto decoded = decodeForceFrame(encodeForceFrame(ForceReading{-2.5, 255, false, true}));
  ASSERT_EQ(decoded.status, DecodeStatus::kOk);
  EXPECT_DOUBLE_EQ(decoded.reading.force_newtons, -2.5);
  EXPECT_EQ(decoded.reading.counter, 255);
  EXPECT_FALSE(decoded.reading.overload);
  EXPECT_TRUE(decoded.reading.fault);
}

TEST(ForceFrame, DecodesAHandWrittenFrame)
{
  // 800.000 N = 800000 mN = 0x000C3500: 00 35 0C 00; no status; counter 0x10; checksum 0x51.
  const auto decoded =
      decodeForceFrame(can::makeFrame(0x190, {0x00, 0x35, 0x0C, 0x00, 0x00, 0x10, 0x00, 0x51}));
  ASSERT_EQ(decoded.status, DecodeStatus::kOk);
  EXPECT_DOUBLE_EQ(decoded.reading.force_newtons, 800.0);
  EXPECT_EQ(decoded.reading.counter, 0x10);
}

TEST(ForceFrame, RejectsBadFrames)
{
  can::Frame frame = encodeForceFrame(ForceReading{10.0, 1, false, false});
  can::Frame short_frame = frame;
  short_frame.dlc = 7;
  EXPECT_EQ(decodeForceFrame(short_frame).status, DecodeStatus::kWrongLength);
  can::Frame corrupted = frame;
  corrupted.data[0] ^= 0x01;
  EXPECT_EQ(decodeForceFrame(corrupted).status, DecodeStatus::kBadChecksum);
  EXPECT_EQ(decodeForceFrame(frame, 0x191).status, DecodeStatus::kWrongId);
  can::Frame extended = frame;
  extended.flags = can::kFlagExtended;
  EXPECT_EQ(decodeForceFrame(extended).status, DecodeStatus::kWrongId);
  can::Frame remote = frame;
  remote.flags = can::kFlagRemote;
  EXPECT_EQ(decodeForceFrame(remote).status, DecodeStatus::kNotDataFrame);
}

TEST(ForceSensorEmulator, SaturatesFlagsOverloadAndCountsUp)
{
  ForceSensorEmulator sensor(800.0, 0x190);
  const auto first = decodeForceFrame(sensor.nextFrame(950.0));
  ASSERT_EQ(first.status, DecodeStatus::kOk);
  EXPECT_DOUBLE_EQ(first.reading.force_newtons, 800.0);
  EXPECT_TRUE(first.reading.overload);
  EXPECT_EQ(first.reading.counter, 0);
  const auto second = decodeForceFrame(sensor.nextFrame(-3.0));
  EXPECT_DOUBLE_EQ(second.reading.force_newtons, 0.0);
  EXPECT_FALSE(second.reading.overload);
  EXPECT_EQ(second.reading.counter, 1);
  for (int index = 0; index < 254; ++index)
    sensor.nextFrame(1.0);
  EXPECT_EQ(decodeForceFrame(sensor.nextFrame(1.0)).reading.counter, 0);  // wrapped after 255
  sensor.setCounterFrozen(true);
  sensor.setFault(true);
  const auto frozen = decodeForceFrame(sensor.nextFrame(1.0));
  EXPECT_EQ(frozen.reading.counter, decodeForceFrame(sensor.nextFrame(1.0)).reading.counter);
  EXPECT_TRUE(frozen.reading.fault);
}

}  // namespace
}  // namespace ifar::force_sensor
