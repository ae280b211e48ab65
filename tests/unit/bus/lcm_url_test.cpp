// The receive buffer every LCM process of the stack asks for: added to udpm:// URLs only, and never over
// a URL's own setting.

#include "bus/lcm_url.hpp"

#include <gtest/gtest.h>

namespace ifar::bus {
namespace {

TEST(LcmUrl, AUdpmUrlGetsTheReceiveBufferAndOtherProvidersAndItsOwnSettingAreKept)
{
  EXPECT_EQ(withReceiveBuffer("", 4194304), "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304");
  EXPECT_EQ(withReceiveBuffer("udpm://239.255.76.67:7781", 1000),
            "udpm://239.255.76.67:7781?recv_buf_size=1000");
  EXPECT_EQ(withReceiveBuffer("udpm://239.255.76.67:7781?", 1000),
            "udpm://239.255.76.67:7781?recv_buf_size=1000");
  EXPECT_EQ(withReceiveBuffer("udpm://239.255.76.67:7781?recv_buf_size=5", 1000),
            "udpm://239.255.76.67:7781?recv_buf_size=5");
  EXPECT_EQ(withReceiveBuffer("udpm://239.255.76.67:7781?ttl=1&recv_buf_size=5", 1000),
            "udpm://239.255.76.67:7781?ttl=1&recv_buf_size=5");
  EXPECT_EQ(withReceiveBuffer("memq://", 1000), "memq://");
  EXPECT_EQ(withReceiveBuffer("udpm://239.255.76.67:7781?ttl=0", 0), "udpm://239.255.76.67:7781?ttl=0");
  EXPECT_EQ(withReceiveBuffer("", 0), "");
}

}  // namespace
}  // namespace ifar::bus
