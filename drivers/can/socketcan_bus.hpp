#pragma once
// CanBus on a Linux SocketCAN interface (can0, vcan0): a non-blocking CAN_RAW socket with kernel id/mask
// filters, error frames (CAN_RAW_ERR_FILTER) folded into the bus state, kernel receive timestamps
// (SO_TIMESTAMP), and FD-sized reads tolerated (CAN_RAW_FD_FRAMES on: classic frames arriving in a
// canfd_frame are accepted, FD frames with more than 8 bytes are counted as bad).

#include <memory>
#include <string>
#include <vector>

#include "drivers/can/can_bus.hpp"

namespace ifar::can {

class SocketCanBus;

struct SocketCanOpenResult {
  std::unique_ptr<SocketCanBus> bus;  // null on failure
  std::string error;                  // why opening failed, naming the interface and the cause
};

class SocketCanBus final : public CanBus {
 public:
  /// Opens a raw socket bound to `interface_name`. Fails (bus null, error set) when the kernel has no
  /// AF_CAN, the interface does not exist, or a socket option cannot be set.
  static SocketCanOpenResult open(const std::string& interface_name);
  ~SocketCanBus() override;

  std::string name() const override { return interface_name_; }
  SendResult send(const Frame& frame) override;
  ReceiveResult receive(std::chrono::microseconds timeout) override;
  void setFilters(const std::vector<Filter>& filters) override;
  BusState state() const override { return state_; }
  BusCounters counters() const override { return counters_; }

  /// Whether the socket also receives frames it sent itself (CAN_RAW_RECV_OWN_MSGS; off by default).
  bool setReceiveOwnFrames(bool enabled);
  /// The socket's file descriptor, for poll() loops. Owned by this object.
  int fileDescriptor() const { return socket_fd_; }

 private:
  SocketCanBus(int socket_fd, std::string interface_name);

  int socket_fd_ = -1;
  std::string interface_name_;
  BusState state_ = BusState::kActive;
  BusCounters counters_;
};

}  // namespace ifar::can
