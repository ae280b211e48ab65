#include <gtest/gtest.h>

#include "common/input_silence.hpp"

namespace {

using ifar::common::InputSilence;

TEST(InputSilence, NamesEachInputSilentLongerThanTheLimit)
{
  InputSilence silence(1'000'000, 1.0);
  const std::size_t packets = silence.watch("VELODYNE_PACKET");
  const std::size_t pose = silence.watch("POSE");
  EXPECT_EQ(silence.problem(1'900'000), "");  // just started: nothing is missing yet
  EXPECT_EQ(silence.problem(2'100'000),
            "no VELODYNE_PACKET for 1.1 s (none since start), no POSE for 1.1 s (none since start)");
  silence.arrived(packets, 2'200'000);
  silence.arrived(pose, 2'300'000);
  EXPECT_EQ(silence.problem(3'200'000), "");
  EXPECT_EQ(silence.problem(3'250'000), "no VELODYNE_PACKET for 1.1 s");
  EXPECT_EQ(silence.problem(5'500'000), "no VELODYNE_PACKET for 3.3 s, no POSE for 3.2 s");
  silence.arrived(pose, 5'500'000);
  EXPECT_EQ(silence.problem(5'500'000), "no VELODYNE_PACKET for 3.3 s");
}

TEST(InputSilence, DurationsAreMaskedForComparison)
{
  EXPECT_EQ(ifar::common::withoutDurations("no lidar packets from 192.168.1.201:2368 for 5.0 s"),
            "no lidar packets from 192.168.1.201:2368 for N s");
  EXPECT_EQ(ifar::common::withoutDurations("no FORCE for 12 s, drive 1 heartbeat lost; 3 s"),
            "no FORCE for N s, drive 1 heartbeat lost; N s");
  EXPECT_EQ(ifar::common::withoutDurations("2 velocity commands refused"), "2 velocity commands refused");
  EXPECT_EQ(ifar::common::withoutDurations("10 samples"), "10 samples");
}

}  // namespace
