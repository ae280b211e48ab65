#include "drivers/can/lcm_bridge_bus.hpp"

#include <algorithm>
#include <chrono>

#include "drivers/can/error_frame.hpp"
#include "drivers/can/frame_queue.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace ifar::can {
namespace {

// Enough to recognise our own frames looped back by LCM, even when a burst is sent at once.
constexpr std::size_t kRecentlySentLimit = 256;

std::int64_t wallClockMicroseconds()
{
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

bool sameMessage(const ifar::can_frame_t& left, const ifar::can_frame_t& right)
{
  return left.utime == right.utime && left.id == right.id && left.flags == right.flags &&
         left.dlc == right.dlc && std::equal(left.data, left.data + 8, right.data);
}

}  // namespace

ifar::can_frame_t toLcm(const Frame& frame)
{
  ifar::can_frame_t message{};
  message.utime = frame.timestamp_us;
  message.id = static_cast<std::int32_t>(frame.id);
  message.flags = static_cast<std::int8_t>(frame.flags);
  message.dlc = static_cast<std::int8_t>(std::min<std::uint8_t>(frame.dlc, kMaxDataLength));
  for (std::size_t index = 0; index < kMaxDataLength; ++index) {
    message.data[index] = index < frame.dlc ? frame.data[index] : 0;
  }
  return message;
}

Frame fromLcm(const ifar::can_frame_t& message, bool* valid)
{
  Frame frame;
  const bool dlc_ok = message.dlc >= 0 && message.dlc <= static_cast<std::int8_t>(kMaxDataLength);
  const bool flags_ok = (message.flags & ~(kFlagExtended | kFlagRemote | kFlagError)) == 0;
  frame.flags = static_cast<std::uint8_t>(message.flags) & (kFlagExtended | kFlagRemote | kFlagError);
  const std::uint32_t id = static_cast<std::uint32_t>(message.id);
  const std::uint32_t id_mask = frame.extended() || frame.error() ? kExtendedIdMask : kStandardIdMask;
  const bool id_ok = (id & ~id_mask) == 0;
  frame.id = id & id_mask;
  frame.dlc = dlc_ok ? static_cast<std::uint8_t>(message.dlc) : kMaxDataLength;
  for (std::size_t index = 0; index < frame.dlc; ++index) {
    frame.data[index] = message.data[index];
  }
  frame.timestamp_us = message.utime;
  if (valid != nullptr) {
    *valid = dlc_ok && flags_ok && id_ok;
  }
  return frame;
}

LcmBridgeBus::LcmBridgeBus(lcm::LCM& lcm, std::string channel) : lcm_(lcm), channel_(std::move(channel))
{
  subscription_ = lcm_.subscribe(channel_, &LcmBridgeBus::handleMessage, this);
}

// Raw, not typed: LCM's typed subscription prints an error for a message that does not decode and drops
// it uncounted; here it counts as a bad frame.
void LcmBridgeBus::handleMessage(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/)
{
  ifar::can_frame_t message{};
  if (!lcmtypes::decodeLcm(message, buffer->data, buffer->data_size).ok()) {
    ++counters_.bad_frames;
    return;
  }
  onMessage(message);
}

LcmBridgeBus::~LcmBridgeBus()
{
  if (subscription_ != nullptr) {
    lcm_.unsubscribe(subscription_);
  }
}

SendResult LcmBridgeBus::send(const Frame& frame)
{
  if (frame.dlc > kMaxDataLength) {
    ++counters_.write_errors;
    return {IoStatus::kError, name() + ": dlc " + std::to_string(frame.dlc) + " > 8"};
  }
  Frame stamped = frame;
  stamped.timestamp_us = wallClockMicroseconds();
  const ifar::can_frame_t message = toLcm(stamped);
  if (lcm_.publish(channel_, &message) != 0) {
    ++counters_.write_errors;
    return {IoStatus::kError, name() + ": LCM publish failed"};
  }
  recently_sent_.push_back(message);
  if (recently_sent_.size() > kRecentlySentLimit) {
    recently_sent_.pop_front();
  }
  ++counters_.frames_sent;
  return {};
}

void LcmBridgeBus::onMessage(const ifar::can_frame_t& message)
{
  const auto own = std::find_if(recently_sent_.begin(), recently_sent_.end(),
                                [&](const ifar::can_frame_t& sent) { return sameMessage(sent, message); });
  if (own != recently_sent_.end()) {
    recently_sent_.erase(own);
    return;
  }
  bool valid = false;
  const Frame frame = fromLcm(message, &valid);
  if (!valid) {
    ++counters_.bad_frames;
    return;
  }
  queue_.push_back(frame);
}

ReceiveResult LcmBridgeBus::receive(std::chrono::microseconds timeout)
{
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    if (const auto frame = takeAcceptedFrame(queue_, filters_, state_, counters_)) {
      return {IoStatus::kOk, *frame, {}};
    }
    const auto remaining =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    const int timeout_ms = static_cast<int>(std::max<std::int64_t>(remaining.count(), 0));
    const int handled = lcm_.handleTimeout(timeout_ms);
    if (handled < 0) {
      return {IoStatus::kError, {}, name() + ": LCM receive failed"};
    }
    if (handled == 0 && queue_.empty()) {
      return {IoStatus::kTimeout, {}, {}};
    }
  }
}

}  // namespace ifar::can
