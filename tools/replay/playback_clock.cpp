#include "tools/replay/playback_clock.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::replay {

std::optional<std::int64_t> PlaybackClock::waitFor(std::int64_t log_time_us, std::int64_t now_us)
{
  if (pause_start_us_) {
    return std::nullopt;
  }
  if (!first_log_time_us_) {
    first_log_time_us_ = log_time_us;
    start_us_ = now_us;
    return 0;
  }
  if (speed_ <= 0.0) {
    return 0;
  }
  // An event stamped before the first one (a log merged from two recorders) is simply late.
  const double log_offset_us = static_cast<double>(log_time_us - *first_log_time_us_);
  const double due_us = static_cast<double>(start_us_) + log_offset_us / speed_;
  return static_cast<std::int64_t>(std::max(0.0, std::ceil(due_us - static_cast<double>(now_us))));
}

void PlaybackClock::pause(std::int64_t now_us)
{
  if (!pause_start_us_) {
    pause_start_us_ = now_us;
  }
}

void PlaybackClock::resume(std::int64_t now_us)
{
  if (pause_start_us_) {
    start_us_ += now_us - *pause_start_us_;
    pause_start_us_.reset();
  }
}

}  // namespace ifar::replay
