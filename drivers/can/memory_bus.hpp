#pragma once
// An in-memory CAN medium for tests and the lock-step simulator: every endpoint attached to the same
// MemoryNetwork receives what the others send (not its own frames, like a SocketCAN raw socket).
// Thread-safe, so a test may run a drive emulator and a client on two threads.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "drivers/can/can_bus.hpp"

namespace ifar::can {

class MemoryBus;

/// The shared medium. Endpoints hold it through shared_ptr: it lives as long as any endpoint does.
class MemoryNetwork : public std::enable_shared_from_this<MemoryNetwork> {
 public:
  static std::shared_ptr<MemoryNetwork> create();
  /// A new endpoint on this network.
  std::unique_ptr<MemoryBus> attach(const std::string& name);
  /// Delivers an error frame to every endpoint (each folds it into its state), as a controller would.
  void injectErrorFrame(const Frame& error_frame);

 private:
  friend class MemoryBus;
  MemoryNetwork() = default;
  void deliver(const MemoryBus* sender, const Frame& frame);
  void detach(const MemoryBus* endpoint);

  std::mutex mutex_;
  std::vector<MemoryBus*> endpoints_;
};

/// Two endpoints on a fresh network, for the common one-to-one test.
struct MemoryBusPair {
  std::unique_ptr<MemoryBus> first;
  std::unique_ptr<MemoryBus> second;
};
MemoryBusPair makeMemoryBusPair();

class MemoryBus final : public CanBus {
 public:
  ~MemoryBus() override;

  std::string name() const override { return "memory:" + name_; }
  SendResult send(const Frame& frame) override;
  ReceiveResult receive(std::chrono::microseconds timeout) override;
  void setFilters(const std::vector<Filter>& filters) override;
  BusState state() const override;
  BusCounters counters() const override;

  /// Frames waiting to be received.
  std::size_t pending() const;

 private:
  friend class MemoryNetwork;
  MemoryBus(std::shared_ptr<MemoryNetwork> network, std::string name);
  void enqueue(const Frame& frame);

  std::shared_ptr<MemoryNetwork> network_;
  std::string name_;
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<Frame> queue_;
  std::vector<Filter> filters_;
  BusState state_ = BusState::kActive;
  BusCounters counters_;
};

}  // namespace ifar::can
