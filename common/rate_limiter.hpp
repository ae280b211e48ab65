#pragma once
// Lets a message through at most once per interval, counting what it held back: for logging bad input
// without flooding the log.

#include <cstdint>

namespace ifar::common {

class RateLimiter {
 public:
  explicit RateLimiter(std::int64_t interval_microseconds) : interval_(interval_microseconds) {}

  /// True when at least one interval passed since the last allowed event (monotonic microseconds).
  bool allow(std::int64_t now_microseconds)
  {
    if (has_allowed_ && now_microseconds - last_allowed_ < interval_) {
      ++suppressed_;
      return false;
    }
    has_allowed_ = true;
    last_allowed_ = now_microseconds;
    return true;
  }

  /// Events held back since the last call; resets the count.
  std::int64_t takeSuppressed()
  {
    const std::int64_t count = suppressed_;
    suppressed_ = 0;
    return count;
  }

 private:
  std::int64_t interval_;
  std::int64_t last_allowed_ = 0;
  std::int64_t suppressed_ = 0;
  bool has_allowed_ = false;
};

}  // namespace ifar::common
