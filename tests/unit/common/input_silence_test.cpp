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
  EXPECT_EQ(silence.problem(2'100'000), "no VELODYNE_PACKET yet, no POSE yet");
  silence.arrived(packets, 2'200'000);
  silence.arrived(pose, 2'300'000);
  EXPECT_EQ(silence.problem(3'200'000), "");
  EXPECT_EQ(silence.problem(3'250'000), "no VELODYNE_PACKET for 1.1 s");
  EXPECT_EQ(silence.problem(5'500'000), "no VELODYNE_PACKET for 3.3 s, no POSE for 3.2 s");
  silence.arrived(pose, 5'500'000);
  EXPECT_EQ(silence.problem(5'500'000), "no VELODYNE_PACKET for 3.3 s");
}

}  // namespace
