// SocketCAN on the build host: only the failure path can be checked here (this kernel has no AF_CAN);
// the real socket is tested under qemu by tests/socketcan.
#include "drivers/can/socketcan_bus.hpp"

#include <gtest/gtest.h>

namespace ifar::can {
namespace {

TEST(SocketCanHost, OpeningAMissingInterfaceFailsWithAClearError)
{
  const auto opened = SocketCanBus::open("ifarnone0");
  EXPECT_EQ(opened.bus, nullptr);
  EXPECT_NE(opened.error.find("ifarnone0"), std::string::npos) << opened.error;
  // Either the kernel has no CAN at all, or it has no such interface: both are said plainly.
  const bool names_cause = opened.error.find("no SocketCAN support") != std::string::npos ||
                           opened.error.find("no CAN interface named") != std::string::npos;
  EXPECT_TRUE(names_cause) << opened.error;
}

TEST(SocketCanHost, RejectsOverlongInterfaceNames)
{
  const auto opened = SocketCanBus::open("an-interface-name-far-too-long");
  EXPECT_EQ(opened.bus, nullptr);
  EXPECT_NE(opened.error.find("longer than"), std::string::npos) << opened.error;
}

}  // namespace
}  // namespace ifar::can
