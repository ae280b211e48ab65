#include "drivers/velodyne/udp_receiver.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "common/time.hpp"

namespace ifar::velodyne {
namespace {
// Large enough for any datagram the VLP-16 sends plus room to notice oversized ones.
constexpr std::size_t kBufferSize = 2048;

std::string errnoText(const std::string& what)
{
  return what + ": " + std::strerror(errno);
}
}  // namespace

UdpReceiver::UdpReceiver(std::uint16_t port, const std::string& bind_address,
                         std::size_t receive_buffer_bytes)
    : buffer_(kBufferSize)
{
  const std::string where = bind_address + ":" + std::to_string(port);
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) {
    last_error_ = errnoText("cannot create a UDP socket for " + where);
    return;
  }
  // No SO_REUSEADDR: a second receiver on the same port (a second stack's driver on this host) would
  // silently take the datagrams; it fails to bind instead and says so.
  const int enable = 1;
  // Best effort: without kernel timestamps receive() falls back to the clock.
  setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMP, &enable, sizeof(enable));
  const int buffer_bytes = static_cast<int>(receive_buffer_bytes);
  setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buffer_bytes, sizeof(buffer_bytes));

  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  if (inet_pton(AF_INET, bind_address.c_str(), &address.sin_addr) != 1) {
    last_error_ = "cannot bind " + where + ": not an IPv4 address";
    close();
    return;
  }
  if (bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    const bool in_use = errno == EADDRINUSE;
    last_error_ = errnoText("cannot bind " + where);
    if (in_use) {
      last_error_ += " (another receiver on this host has the port: give each stack its own port)";
    }
    close();
    return;
  }
  sockaddr_in bound{};
  socklen_t bound_size = sizeof(bound);
  if (getsockname(fd_, reinterpret_cast<sockaddr*>(&bound), &bound_size) == 0) {
    port_ = ntohs(bound.sin_port);
  }
}

UdpReceiver::~UdpReceiver()
{
  close();
}

UdpReceiver::UdpReceiver(UdpReceiver&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      port_(other.port_),
      last_error_(std::move(other.last_error_)),
      buffer_(std::move(other.buffer_))
{
}

UdpReceiver& UdpReceiver::operator=(UdpReceiver&& other) noexcept
{
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    port_ = other.port_;
    last_error_ = std::move(other.last_error_);
    buffer_ = std::move(other.buffer_);
  }
  return *this;
}

void UdpReceiver::close()
{
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

ReceiveStatus UdpReceiver::receive(ReceivedDatagram& datagram)
{
  if (fd_ < 0) {
    return ReceiveStatus::kError;
  }
  iovec io{buffer_.data(), buffer_.size()};
  sockaddr_in source{};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timeval))] = {};
  msghdr message{};
  message.msg_name = &source;
  message.msg_namelen = sizeof(source);
  message.msg_iov = &io;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof(control);
  // MSG_TRUNC makes recvmsg return the datagram's real length even when it did not fit.
  const ssize_t received = recvmsg(fd_, &message, MSG_TRUNC);
  if (received < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) {
      return ReceiveStatus::kWouldBlock;
    }
    last_error_ = errnoText("receive on port " + std::to_string(port_));
    return ReceiveStatus::kError;
  }
  datagram.wire_size = static_cast<std::size_t>(received);
  datagram.payload = common::ByteView(buffer_.data(), std::min(datagram.wire_size, buffer_.size()));
  datagram.source_address = ntohl(source.sin_addr.s_addr);
  datagram.source_port = ntohs(source.sin_port);
  datagram.kernel_timestamp = false;
  for (cmsghdr* header = CMSG_FIRSTHDR(&message); header != nullptr; header = CMSG_NXTHDR(&message, header)) {
    if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_TIMESTAMP) {
      timeval stamp{};
      std::memcpy(&stamp, CMSG_DATA(header), sizeof(stamp));
      datagram.receive_time_us = static_cast<std::int64_t>(stamp.tv_sec) * 1'000'000 + stamp.tv_usec;
      datagram.kernel_timestamp = true;
    }
  }
  if (!datagram.kernel_timestamp) {
    datagram.receive_time_us = common::nowMicroseconds();
  }
  return ReceiveStatus::kDatagram;
}

}  // namespace ifar::velodyne
