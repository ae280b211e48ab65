#include "tools/replay_test/log_clock_feed.hpp"

#include <utility>

namespace ifar::replay_test {

LogClockFeed::LogClockFeed(std::set<std::string> inputs, LogClockHooks hooks)
    : inputs_(std::move(inputs)), hooks_(std::move(hooks))
{
}

void LogClockFeed::add(const lcm_log::LogEvent& event)
{
  if (!started_ || event.timestamp_us > current_utime_) {
    if (started_) {
      hooks_.timers(current_utime_);
    }
    started_ = true;
    current_utime_ = event.timestamp_us;
    hooks_.time(current_utime_);
  }
  if (inputs_.count(event.channel) > 0) {
    ++inputs_delivered_;
    hooks_.deliver(event);
  }
}

void LogClockFeed::finish()
{
  if (started_) {
    hooks_.timers(current_utime_);
  }
}

}  // namespace ifar::replay_test
