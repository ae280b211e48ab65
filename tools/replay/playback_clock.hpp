#pragma once
// When each event of a log is due on the player's clock: the log's own time, scaled by the playback speed,
// from the moment the first event was played, with the time spent paused added on. No clock of its own:
// every call is given the current time, so tests run it on made-up times.

#include <cstdint>
#include <optional>

namespace ifar::replay {

class PlaybackClock {
 public:
  /// `speed`: log seconds per second of playback; 0 plays every event at once (as fast as possible).
  explicit PlaybackClock(double speed) : speed_(speed) {}

  /// Microseconds from `now_us` until the event stamped `log_time_us` is due; 0 when it is due (or late),
  /// nothing while paused. The first event asked about is due at once and anchors the log's time.
  std::optional<std::int64_t> waitFor(std::int64_t log_time_us, std::int64_t now_us);

  void pause(std::int64_t now_us);
  void resume(std::int64_t now_us);
  bool paused() const { return pause_start_us_.has_value(); }

 private:
  double speed_;
  std::optional<std::int64_t> first_log_time_us_;
  std::int64_t start_us_ = 0;  // when the first event was due, shifted by every pause
  std::optional<std::int64_t> pause_start_us_;
};

}  // namespace ifar::replay
