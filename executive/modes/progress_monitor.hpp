#pragma once
// Progress over the whole loop. Each part of the executive has its own stall clock, but the loop of
// planner and executive together can repeat itself without any part standing still: a route that flips
// between two doors, an approach round an object that never gets to its contact, a push undone by the
// next replan. The monitor watches what the loop is for: the path still to drive to the goal. When that
// has not shrunk by a margin, and the vehicle has not reached new ground either, for a bounded time, it
// calls for an escalation: the executive drops what it is stuck on and reports it.

#include <cstdint>
#include <optional>
#include <set>
#include <utility>

#include "common/geometry/point.hpp"

namespace ifar::executive {

struct ProgressSettings {
  /// No progress for this long calls for an escalation (0: never). At the follower's 0.6 m/s top speed a
  /// minute is some 30 m of driving: more than a detour round a room's obstacles or an approach and push
  /// need without the way to the goal getting shorter or the vehicle reaching new ground.
  double timeout_s = 60.0;
  /// The remaining path must beat its best by this much to count: about half the vehicle's 0.9 m length,
  /// so dithering and the path's re-anchoring on the vehicle do not.
  double margin_m = 0.5;
  /// Entering a square of this side the vehicle has not been in counts as progress (exploring round an
  /// obstacle first seen on the way lengthens the path). A little over twice the vehicle's length: a loop
  /// on the spot or round one door stays within squares already visited.
  double new_ground_m = 2.0;
};

class ProgressMonitor {
 public:
  explicit ProgressMonitor(const ProgressSettings& settings) : settings_(settings) {}

  /// A new goal: nothing is known of the way to it.
  void startGoal();
  /// One cycle at `now_us` with the vehicle at `position` and `remaining_m` of path to the goal.
  /// `counting` false (waiting for a replan, stopped, idle): the time does not count as no progress.
  /// True on the cycle an escalation is due; the clock then starts again.
  bool update(std::int64_t now_us, const geometry::Point& position, double remaining_m, bool counting);
  /// Seconds without progress so far.
  double stuckSeconds() const { return stuck_us_ * 1e-6; }
  /// The shortest remaining path seen since the last escalation (none before the first cycle).
  std::optional<double> bestRemaining() const { return best_remaining_m_; }

 private:
  /// True when `position` lies in a square not visited before (and marks it).
  bool newGround(const geometry::Point& position);

  ProgressSettings settings_;
  std::optional<double> best_remaining_m_;
  std::int64_t stuck_us_ = 0;
  std::optional<std::int64_t> last_us_;
  std::set<std::pair<std::int64_t, std::int64_t>> visited_;
};

}  // namespace ifar::executive
