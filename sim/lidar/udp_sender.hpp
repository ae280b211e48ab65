#pragma once
// A connected UDP socket that sends datagrams to one host:port (the simulated VLP-16's data port).
// RAII: the socket closes with the object. Send failures are counted, not thrown.

#include <cstdint>
#include <string>

#include "common/span.hpp"

namespace ifar::sim {

class UdpSender {
 public:
  /// Throws std::runtime_error naming host and port when the address is not an IPv4 address or the
  /// socket cannot be made.
  UdpSender(const std::string& host, std::uint16_t port);
  ~UdpSender();
  UdpSender(const UdpSender&) = delete;
  UdpSender& operator=(const UdpSender&) = delete;

  /// False (and counted) when the datagram could not be sent.
  bool send(common::ByteView datagram);
  std::int64_t sent() const { return sent_; }
  std::int64_t failures() const { return failures_; }

 private:
  int socket_ = -1;
  std::int64_t sent_ = 0;
  std::int64_t failures_ = 0;
};

}  // namespace ifar::sim
