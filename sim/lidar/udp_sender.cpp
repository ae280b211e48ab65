#include "sim/lidar/udp_sender.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace ifar::sim {

UdpSender::UdpSender(const std::string& host, std::uint16_t port)
{
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  const std::string where = host + ":" + std::to_string(port);
  if (inet_pton(AF_INET, host.c_str(), &address.sin_addr) != 1) {
    throw std::runtime_error("lidar destination " + where + ": host is not an IPv4 address");
  }
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) {
    throw std::runtime_error("lidar destination " + where + ": socket: " + std::strerror(errno));
  }
  // A broadcast destination (e.g. 255.255.255.255, as a real sensor uses) needs the option.
  const int enable = 1;
  ::setsockopt(socket_, SOL_SOCKET, SO_BROADCAST, &enable, sizeof(enable));
  if (::connect(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    const std::string problem = std::strerror(errno);
    ::close(socket_);
    throw std::runtime_error("lidar destination " + where + ": connect: " + problem);
  }
}

UdpSender::~UdpSender()
{
  if (socket_ >= 0) {
    ::close(socket_);
  }
}

bool UdpSender::send(common::ByteView datagram)
{
  // Nobody listening yields ECONNREFUSED on a connected socket: counted, the sensor keeps sending.
  const ssize_t written = ::send(socket_, datagram.data(), datagram.size(), MSG_DONTWAIT);
  if (written != static_cast<ssize_t>(datagram.size())) {
    ++failures_;
    return false;
  }
  ++sent_;
  return true;
}

}  // namespace ifar::sim
