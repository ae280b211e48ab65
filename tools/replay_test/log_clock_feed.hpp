#pragma once
// A log fed to a node on the log's own clock, as the headless runner and a daemon's loop meet their inputs:
// at each logged time, first every input event of that time (in log order), then the node's timers due
// then. The events come one by one in log order (add), so a log of any size streams through; finish() runs
// the timers of the last time. What the node does with an event or a time is the hooks' business.

#include <cstdint>
#include <functional>
#include <set>
#include <string>

#include "common/lcm_log/log_reader.hpp"

namespace ifar::replay_test {

struct LogClockHooks {
  std::function<void(std::int64_t utime)> time;                 // the clock moves to a new logged time
  std::function<void(const lcm_log::LogEvent& event)> deliver;  // an input event of the current time
  std::function<void(std::int64_t utime)> timers;               // after the inputs of that time
};

class LogClockFeed {
 public:
  LogClockFeed(std::set<std::string> inputs, LogClockHooks hooks);

  /// The next event of the log (timestamps never decreasing in a sound log; an earlier one counts as the
  /// current time).
  void add(const lcm_log::LogEvent& event);
  /// The last logged time's timers; nothing when no event came.
  void finish();

  std::int64_t inputsDelivered() const { return inputs_delivered_; }

 private:
  std::set<std::string> inputs_;
  LogClockHooks hooks_;
  bool started_ = false;
  std::int64_t current_utime_ = 0;
  std::int64_t inputs_delivered_ = 0;
};

}  // namespace ifar::replay_test
