#pragma once
// CanBus over LCM (library ifar_can_lcm_bridge, the only CAN code that includes LCM): frames travel as
// ifar::can_frame_t on one channel (e.g. CAN_VEHICLE). Used where the kernel has no SocketCAN, and by
// the simulator to stand in for the vehicle's bus. Own frames that LCM loops back are dropped, as a
// SocketCAN raw socket does not receive its own frames.

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "drivers/can/can_bus.hpp"
#include "ifar/can_frame_t.hpp"

namespace ifar::can {

ifar::can_frame_t toLcm(const Frame& frame);
/// Nullopt-free: invalid fields are clamped (dlc to 8); returns false in `valid` for a bad dlc.
Frame fromLcm(const ifar::can_frame_t& message, bool* valid = nullptr);

class LcmBridgeBus final : public CanBus {
 public:
  /// `lcm` must outlive this object; it is used from receive() and send() only.
  LcmBridgeBus(lcm::LCM& lcm, std::string channel);
  ~LcmBridgeBus() override;

  std::string name() const override { return "lcm:" + channel_; }
  SendResult send(const Frame& frame) override;
  /// Handles LCM traffic until a frame is queued or the timeout passes.
  ReceiveResult receive(std::chrono::microseconds timeout) override;
  void setFilters(const std::vector<Filter>& filters) override { filters_ = filters; }
  BusState state() const override { return state_; }
  BusCounters counters() const override { return counters_; }

  /// Queues a frame received through some other LCM loop (when the caller owns the handling loop).
  void onMessage(const ifar::can_frame_t& message);

 private:
  void handleMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  std::string channel_;
  lcm::Subscription* subscription_ = nullptr;
  std::deque<Frame> queue_;
  std::deque<ifar::can_frame_t> recently_sent_;
  std::vector<Filter> filters_;
  BusState state_ = BusState::kActive;
  BusCounters counters_;
};

}  // namespace ifar::can
