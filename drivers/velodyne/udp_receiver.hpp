#pragma once
// A non-blocking UDP socket bound to one port, owning its file descriptor. Each datagram comes with the
// kernel's receive time (SO_TIMESTAMP) when available, else the wall clock read right after recvmsg.

#include <cstdint>
#include <string>
#include <vector>

#include "common/span.hpp"

namespace ifar::velodyne {

enum class ReceiveStatus : std::uint8_t {
  kDatagram,    // `datagram` is filled in
  kWouldBlock,  // nothing pending
  kError,       // the socket reported an error (see UdpReceiver::lastError())
};

struct ReceivedDatagram {
  common::ByteView payload;          // valid until the next receive()
  std::size_t wire_size = 0;         // the datagram's real size; larger than payload.size() when cut
  std::int64_t receive_time_us = 0;  // microseconds since the Unix epoch
  bool kernel_timestamp = false;     // true when receive_time_us came from SO_TIMESTAMP
  std::uint32_t source_address = 0;  // IPv4, host byte order
  std::uint16_t source_port = 0;
};

class UdpReceiver {
 public:
  /// Binds 0.0.0.0:`port` (or `bind_address`), alone: a port another socket holds is an error. On failure
  /// isOpen() is false and lastError() names the address and the reason. `port` 0 picks a free port (see
  /// port()).
  explicit UdpReceiver(std::uint16_t port, const std::string& bind_address = "0.0.0.0",
                       std::size_t receive_buffer_bytes = 4 * 1024 * 1024);
  ~UdpReceiver();
  UdpReceiver(const UdpReceiver&) = delete;
  UdpReceiver& operator=(const UdpReceiver&) = delete;
  UdpReceiver(UdpReceiver&& other) noexcept;
  UdpReceiver& operator=(UdpReceiver&& other) noexcept;

  bool isOpen() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  std::uint16_t port() const { return port_; }
  const std::string& lastError() const { return last_error_; }

  /// Reads one pending datagram without blocking.
  ReceiveStatus receive(ReceivedDatagram& datagram);

 private:
  void close();

  int fd_ = -1;
  std::uint16_t port_ = 0;
  std::string last_error_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace ifar::velodyne
