#include "common/lcm_log/strict_event_reader.hpp"

#include <utility>

namespace ifar::lcm_log {

bool StrictEventReader::next(LogEvent& event)
{
  if (!started_) {
    started_ = true;
    current_start_ = reader_.position();
    has_current_ = reader_.next(current_) && reader_.clean();
  }
  if (!has_current_) {
    return false;
  }
  const std::uint64_t current_end = reader_.position();
  const bool more = reader_.next(upcoming_);
  if (!reader_.clean()) {
    has_current_ = false;
    const LogProblem& first = reader_.problems().front();
    // Right after the event, a header with a sync word confirms its length (the header itself may be bad);
    // anything else may be the event's own bytes miscounted.
    if (first.offset == current_end && first.kind == LogProblemKind::kBadSyncWord) {
      held_back_ = true;
      held_back_start_ = current_start_;
      return false;
    }
    event = std::move(current_);
    return true;
  }
  std::swap(event, current_);
  std::swap(current_, upcoming_);
  has_current_ = more;
  current_start_ = current_end;
  return true;
}

std::string StrictEventReader::problem() const
{
  if (reader_.clean()) {
    return {};
  }
  std::string text =
      reader_.problems().empty() ? reader_.problemSummary() : reader_.problems().front().description;
  if (held_back_) {
    text += "; the event at byte " + std::to_string(held_back_start_) +
            " before it is left out: its length does not end where an event starts";
  }
  return text;
}

}  // namespace ifar::lcm_log
