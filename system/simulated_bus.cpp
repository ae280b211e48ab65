#include "system/simulated_bus.hpp"

#include <algorithm>

#include "drivers/can/lcm_bridge_bus.hpp"

namespace ifar::runner {
namespace {

template <typename Message>
std::vector<std::uint8_t> encode(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace

SimulatedBus::SimulatedBus(std::string can_channel) : can_channel_(std::move(can_channel)) {}

void SimulatedBus::publish(std::string channel, BusMessage message)
{
  Publication publication;
  publication.channel = std::move(channel);
  publication.message = std::move(message);
  queue_.push_back(std::move(publication));
}

void SimulatedBus::subscribeFrames(CanParticipant participant,
                                   std::function<void(const can::Frame&, std::int64_t)> handler)
{
  frame_subscribers_[participant] = std::move(handler);
}

void SimulatedBus::publishFrame(CanParticipant sender, const can::Frame& frame)
{
  Publication publication;
  publication.channel = can_channel_;
  publication.frame = frame;
  publication.sender = sender;
  publication.delivered.push_back(sender);  // a CAN controller does not receive its own frames
  queue_.push_back(std::move(publication));
}

void SimulatedBus::deliverMessage(const Publication& publication, std::int64_t now_us)
{
  const auto subscribers = subscribers_.find(publication.channel);
  if (subscribers == subscribers_.end()) {
    return;
  }
  for (const auto& handler : subscribers->second) {
    handler(*publication.message, now_us);
  }
}

void SimulatedBus::deliverFrame(Publication& publication, std::int64_t now_us)
{
  for (const auto& [participant, handler] : frame_subscribers_) {
    if (std::find(publication.delivered.begin(), publication.delivered.end(), participant) ==
        publication.delivered.end()) {
      handler(*publication.frame, now_us);
    }
  }
}

void SimulatedBus::deliver(std::int64_t now_us)
{
  while (!queue_.empty()) {
    Publication publication = std::move(queue_.front());
    queue_.pop_front();
    record(publication, now_us);
    if (publication.message) {
      deliverMessage(publication, now_us);
    } else {
      deliverFrame(publication, now_us);
    }
  }
}

void SimulatedBus::deliverFramesTo(CanParticipant participant, std::int64_t now_us)
{
  const auto handler = frame_subscribers_.find(participant);
  if (handler == frame_subscribers_.end()) {
    return;
  }
  // Only what is queued now: frames the handler sends go out with the next delivery.
  const std::size_t queued = queue_.size();
  for (std::size_t index = 0; index < queued; ++index) {
    Publication& publication = queue_[index];
    if (!publication.frame || std::find(publication.delivered.begin(), publication.delivered.end(),
                                        participant) != publication.delivered.end()) {
      continue;
    }
    publication.delivered.push_back(participant);
    handler->second(*publication.frame, now_us);
  }
}

std::string SimulatedBus::recordTo(const std::string& path)
{
  auto log = std::make_unique<lcm_log::LogWriter>(path);
  if (!log->openError().empty()) {
    return log->openError();
  }
  log_ = std::move(log);
  return {};
}

void SimulatedBus::record(const Publication& publication, std::int64_t now_us)
{
  if (!log_) {
    return;
  }
  const std::vector<std::uint8_t> bytes =
      publication.message
          ? std::visit([](const auto& message) { return encode(message); }, *publication.message)
          : encode(can::toLcm(*publication.frame));
  if (!log_->write(publication.channel, now_us, common::ByteView(bytes.data(), bytes.size()))) {
    recording_error_ = log_->writeError();
    log_.reset();
  }
}

}  // namespace ifar::runner
