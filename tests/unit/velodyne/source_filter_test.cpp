// The driver keeps to its own sensor: datagrams from another source are counted as bad, and a second
// receiver cannot share the port.

#include <gtest/gtest.h>

#include <spdlog/sinks/null_sink.h>

#include "drivers/velodyne/packet_forwarder.hpp"
#include "drivers/velodyne/udp_receiver.hpp"

namespace ifar::velodyne {
namespace {

std::shared_ptr<spdlog::logger> quietLogger()
{
  return std::make_shared<spdlog::logger>("velodyne_test", std::make_shared<spdlog::sinks::null_sink_mt>());
}

constexpr std::uint32_t kSensor = (192U << 24) | (168U << 16) | (1U << 8) | 201U;
constexpr std::uint32_t kElsewhere = (192U << 24) | (168U << 16) | (1U << 8) | 77U;

TEST(VelodyneSourceFilter, OnlyTheConfiguredSensorIsAccepted)
{
  DriverSettings settings;
  settings.sensor_address = "192.168.1.201";
  PacketForwarder forwarder(settings, quietLogger());
  EXPECT_TRUE(forwarder.acceptsSource(kSensor, 1));
  EXPECT_FALSE(forwarder.acceptsSource(kElsewhere, 2));
  EXPECT_FALSE(forwarder.acceptsSource(kElsewhere, 3));
  EXPECT_EQ(forwarder.monitor().counts().bad_packets, 2);
  EXPECT_EQ(forwarder.monitor().counts().packets_received, 2);
  EXPECT_EQ(forwarder.statusReport(1.0, 4).last_error,
            "datagram from 192.168.1.77, not the sensor 192.168.1.201");
}

TEST(VelodyneSourceFilter, WithoutASensorAddressEverySourceIsAccepted)
{
  PacketForwarder forwarder(DriverSettings{}, quietLogger());
  EXPECT_TRUE(forwarder.acceptsSource(kElsewhere, 1));
  EXPECT_EQ(forwarder.monitor().counts().bad_packets, 0);
}

TEST(VelodyneSourceFilter, ASecondReceiverOnThePortFailsToBindAndSaysWhy)
{
  const UdpReceiver first(0, "127.0.0.1");
  ASSERT_TRUE(first.isOpen()) << first.lastError();
  const UdpReceiver second(first.port(), "127.0.0.1");
  EXPECT_FALSE(second.isOpen());
  EXPECT_EQ(second.lastError(),
            "cannot bind 127.0.0.1:" + std::to_string(first.port()) +
                ": Address already in use (another receiver on this host has the port: give "
                "each stack its own port)");
}

}  // namespace
}  // namespace ifar::velodyne
