#include "drivers/velodyne/udp_receiver.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <vector>

#include "common/time.hpp"

namespace ifar::velodyne {
namespace {

// A sending socket for the test, closed on scope exit.
class Sender {
 public:
  Sender() : fd_(socket(AF_INET, SOCK_DGRAM, 0)) {}
  ~Sender() { close(fd_); }
  Sender(const Sender&) = delete;
  Sender& operator=(const Sender&) = delete;

  void sendTo(std::uint16_t port, const std::vector<std::uint8_t>& bytes) const
  {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&address),
                     sizeof(address)),
              static_cast<ssize_t>(bytes.size()));
  }

 private:
  int fd_;
};

ReceiveStatus receiveWithin(UdpReceiver& receiver, ReceivedDatagram& datagram, int timeout_ms)
{
  pollfd descriptor{receiver.fd(), POLLIN, 0};
  poll(&descriptor, 1, timeout_ms);
  return receiver.receive(datagram);
}

TEST(VelodyneUdpReceiver, ReceivesWithKernelTimestamp)
{
  UdpReceiver receiver(0, "127.0.0.1");
  ASSERT_TRUE(receiver.isOpen()) << receiver.lastError();
  ASSERT_NE(receiver.port(), 0);
  ReceivedDatagram datagram;
  EXPECT_EQ(receiver.receive(datagram), ReceiveStatus::kWouldBlock);

  const std::int64_t before = common::nowMicroseconds();
  Sender sender;
  std::vector<std::uint8_t> payload(1206);
  for (std::size_t index = 0; index < payload.size(); ++index) {
    payload[index] = static_cast<std::uint8_t>(index * 7);
  }
  sender.sendTo(receiver.port(), payload);
  ASSERT_EQ(receiveWithin(receiver, datagram, 1000), ReceiveStatus::kDatagram);
  const std::int64_t after = common::nowMicroseconds();
  EXPECT_EQ(datagram.wire_size, 1206U);
  EXPECT_EQ(std::vector<std::uint8_t>(datagram.payload.begin(), datagram.payload.end()), payload);
  EXPECT_TRUE(datagram.kernel_timestamp);
  EXPECT_GE(datagram.receive_time_us, before - 1000);
  EXPECT_LE(datagram.receive_time_us, after);
  EXPECT_EQ(datagram.source_address, 0x7F000001U);
}

TEST(VelodyneUdpReceiver, OversizedDatagramReportsItsRealSize)
{
  UdpReceiver receiver(0, "127.0.0.1");
  ASSERT_TRUE(receiver.isOpen()) << receiver.lastError();
  Sender sender;
  sender.sendTo(receiver.port(), std::vector<std::uint8_t>(5000, 1));
  ReceivedDatagram datagram;
  ASSERT_EQ(receiveWithin(receiver, datagram, 1000), ReceiveStatus::kDatagram);
  EXPECT_EQ(datagram.wire_size, 5000U);
  EXPECT_LT(datagram.payload.size(), datagram.wire_size);
}

TEST(VelodyneUdpReceiver, BindFailureIsReportedNotThrown)
{
  UdpReceiver first(0, "127.0.0.1");
  ASSERT_TRUE(first.isOpen());
  UdpReceiver bad_address(0, "not-an-address");
  EXPECT_FALSE(bad_address.isOpen());
  EXPECT_NE(bad_address.lastError().find("not-an-address:0"), std::string::npos) << bad_address.lastError();
  ReceivedDatagram datagram;
  EXPECT_EQ(bad_address.receive(datagram), ReceiveStatus::kError);
}

TEST(VelodyneUdpReceiver, MoveTransfersTheSocket)
{
  UdpReceiver original(0, "127.0.0.1");
  const int fd = original.fd();
  UdpReceiver moved(std::move(original));
  EXPECT_EQ(moved.fd(), fd);
  EXPECT_FALSE(original.isOpen());  // NOLINT(bugprone-use-after-move): checking the moved-from state
}

}  // namespace
}  // namespace ifar::velodyne
