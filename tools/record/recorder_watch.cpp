#include "tools/record/recorder_watch.hpp"

#include <array>
#include <cstdio>

#include "ifar/heartbeat_t.hpp"

namespace ifar::record {

void RecorderWatch::onMessage(std::int64_t now_us)
{
  ++unwritten_messages_;
  if (!first_unwritten_us_) {
    first_unwritten_us_ = now_us;
  }
}

namespace {
/// With nothing recorded arriving this long after the file opened there is nothing to wait for.
constexpr std::int64_t kQuietOpenUs = 1'000'000;
}  // namespace

void RecorderWatch::onLogFile(const std::string& path, std::int64_t now_us)
{
  if (!opened_us_) {
    opened_us_ = now_us;
  }
  path_ = path;
  size_.reset();
  size_unreadable_ = false;
}

void RecorderWatch::onFileSize(std::optional<std::uint64_t> size, std::int64_t /*now_us*/)
{
  size_unreadable_ = !size.has_value();
  if (!size) {
    return;
  }
  if (*size > 0) {
    recording_ = true;
  }
  if (!size_ || *size > *size_) {
    // Whatever arrived before this growth counts as written: the logger writes in arrival order.
    unwritten_messages_ = 0;
    first_unwritten_us_.reset();
  }
  size_ = size;
}

void RecorderWatch::onLoggerExit(const std::string& how)
{
  exit_ = how;
}

RecorderHealth RecorderWatch::health(std::int64_t now_us) const
{
  RecorderHealth health;
  health.level = heartbeat_t::HEALTH_ERROR;
  if (exit_) {
    health.message = "lcm-logger " + *exit_ + ": nothing is recorded";
    return health;
  }
  if (!path_.empty() && size_unreadable_) {
    health.message = "log file " + path_ + " cannot be read (removed?): its messages may be lost";
    return health;
  }
  if (first_unwritten_us_ && now_us - *first_unwritten_us_ >= stall_after_us_) {
    std::array<char, 32> seconds{};
    std::snprintf(seconds.data(), seconds.size(), "%.1f",
                  static_cast<double>(now_us - *first_unwritten_us_) * 1e-6);
    health.message = path_.empty() ? "lcm-logger has opened no log file"
                                   : "log file " + path_ + " has not grown for " + seconds.data() + " s";
    health.message +=
        " while " + std::to_string(unwritten_messages_) + " messages arrived (disk full? logger stuck?)";
    return health;
  }
  if (!recording_) {
    if (path_.empty()) {
      health.level = heartbeat_t::HEALTH_DEGRADED;
      health.message = "waiting for lcm-logger to open its log file";
      return health;
    }
    if (unwritten_messages_ > 0 || now_us - *opened_us_ < kQuietOpenUs) {
      health.level = heartbeat_t::HEALTH_DEGRADED;
      health.message = "waiting for lcm-logger to write its first message to " + path_;
      return health;
    }
  }
  health.level = heartbeat_t::HEALTH_OK;
  return health;
}

}  // namespace ifar::record
