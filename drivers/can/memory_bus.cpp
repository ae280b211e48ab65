#include "drivers/can/memory_bus.hpp"

#include <algorithm>

#include "drivers/can/error_frame.hpp"
#include "drivers/can/frame_queue.hpp"

namespace ifar::can {

std::shared_ptr<MemoryNetwork> MemoryNetwork::create()
{
  return std::shared_ptr<MemoryNetwork>(new MemoryNetwork());
}

std::unique_ptr<MemoryBus> MemoryNetwork::attach(const std::string& name)
{
  std::unique_ptr<MemoryBus> endpoint(new MemoryBus(shared_from_this(), name));
  const std::lock_guard<std::mutex> lock(mutex_);
  endpoints_.push_back(endpoint.get());
  return endpoint;
}

void MemoryNetwork::injectErrorFrame(const Frame& error_frame)
{
  deliver(nullptr, error_frame);
}

void MemoryNetwork::deliver(const MemoryBus* sender, const Frame& frame)
{
  const std::lock_guard<std::mutex> lock(mutex_);
  for (MemoryBus* endpoint : endpoints_) {
    if (endpoint != sender) {
      endpoint->enqueue(frame);
    }
  }
}

void MemoryNetwork::detach(const MemoryBus* endpoint)
{
  const std::lock_guard<std::mutex> lock(mutex_);
  endpoints_.erase(std::remove(endpoints_.begin(), endpoints_.end(), endpoint), endpoints_.end());
}

MemoryBusPair makeMemoryBusPair()
{
  auto network = MemoryNetwork::create();
  MemoryBusPair pair;
  pair.first = network->attach("first");
  pair.second = network->attach("second");
  return pair;
}

MemoryBus::MemoryBus(std::shared_ptr<MemoryNetwork> network, std::string name)
    : network_(std::move(network)), name_(std::move(name))
{
}

MemoryBus::~MemoryBus()
{
  network_->detach(this);
}

SendResult MemoryBus::send(const Frame& frame)
{
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (state_ == BusState::kBusOff) {
      ++counters_.write_errors;
      return {IoStatus::kError, "memory:" + name_ + ": bus-off, frame not sent"};
    }
    if (frame.dlc > kMaxDataLength) {
      ++counters_.write_errors;
      return {IoStatus::kError, "memory:" + name_ + ": dlc " + std::to_string(frame.dlc) + " > 8"};
    }
    ++counters_.frames_sent;
  }
  network_->deliver(this, frame);
  return {};
}

void MemoryBus::enqueue(const Frame& frame)
{
  const std::lock_guard<std::mutex> lock(mutex_);
  queue_.push_back(frame);
  arrived_.notify_all();
}

ReceiveResult MemoryBus::receive(std::chrono::microseconds timeout)
{
  std::unique_lock<std::mutex> lock(mutex_);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    if (const auto frame = takeAcceptedFrame(queue_, filters_, state_, counters_)) {
      return {IoStatus::kOk, *frame, {}};
    }
    if (arrived_.wait_until(lock, deadline) == std::cv_status::timeout && queue_.empty()) {
      return {IoStatus::kTimeout, {}, {}};
    }
  }
}

void MemoryBus::setFilters(const std::vector<Filter>& filters)
{
  const std::lock_guard<std::mutex> lock(mutex_);
  filters_ = filters;
}

BusState MemoryBus::state() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

BusCounters MemoryBus::counters() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

std::size_t MemoryBus::pending() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return queue_.size();
}

}  // namespace ifar::can
