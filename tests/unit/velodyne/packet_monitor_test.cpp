#include "drivers/velodyne/packet_monitor.hpp"

#include <gtest/gtest.h>

namespace ifar::velodyne {
namespace {

PacketInfo validAt(std::uint32_t time_past_hour, ReturnMode mode = ReturnMode::kStrongest)
{
  PacketInfo info;
  info.status = PacketStatus::kOk;
  info.return_mode = mode;
  info.device_time_past_hour = time_past_hour;
  return info;
}

TEST(VelodynePacketMonitor, PacketIntervals)
{
  EXPECT_NEAR(packetIntervalMicroseconds(ReturnMode::kStrongest), 1327.104, 1e-9);
  EXPECT_NEAR(packetIntervalMicroseconds(ReturnMode::kDual), 663.552, 1e-9);
}

TEST(VelodynePacketMonitor, CountsGapsInDeviceTimeAsDrops)
{
  PacketMonitor monitor;
  monitor.recordValid(validAt(1000));
  monitor.recordValid(validAt(2327));             // next packet: no drop
  monitor.recordValid(validAt(2327 + 3 * 1327));  // two packets missing
  EXPECT_EQ(monitor.counts().dropped_packets, 2);
  EXPECT_EQ(monitor.counts().packets_valid, 3);
}

TEST(VelodynePacketMonitor, DualReturnIntervalAndHourWrap)
{
  PacketMonitor monitor;
  monitor.recordValid(validAt(3'599'999'800U, ReturnMode::kDual));
  monitor.recordValid(validAt(464U, ReturnMode::kDual));  // 664 us later, across the hour
  EXPECT_EQ(monitor.counts().dropped_packets, 0);
  monitor.recordValid(validAt(464U + 4 * 664, ReturnMode::kDual));
  EXPECT_EQ(monitor.counts().dropped_packets, 3);
  EXPECT_EQ(monitor.counts().timestamp_jumps, 0);
}

TEST(VelodynePacketMonitor, LongGapsAreJumpsNotDrops)
{
  PacketMonitor monitor;
  monitor.recordValid(validAt(1'000'000));
  monitor.recordValid(validAt(5'000'000));
  monitor.recordValid(validAt(4'000'000));  // backwards: a restart or reordering
  EXPECT_EQ(monitor.counts().dropped_packets, 0);
  EXPECT_EQ(monitor.counts().timestamp_jumps, 2);
}

TEST(VelodynePacketMonitor, BadPacketsAndRates)
{
  PacketMonitor monitor;
  monitor.recordReceived();
  monitor.recordReceived();
  monitor.recordBad("wrong size");
  monitor.recordValid(validAt(0));
  EXPECT_EQ(monitor.counts().packets_received, 2);
  EXPECT_EQ(monitor.counts().bad_packets, 1);
  EXPECT_EQ(monitor.counts().last_error, "wrong size");
  EXPECT_EQ(monitor.takeValidSinceLastReport(), 1);
  EXPECT_EQ(monitor.takeValidSinceLastReport(), 0);
}

}  // namespace
}  // namespace ifar::velodyne
