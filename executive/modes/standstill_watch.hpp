#pragma once
// Tells when the vehicle has got nowhere for a while: neither moved nor turned enough since it was last
// anchored (by the caller, or by itself whenever it moves). With wheel odometry, motion counts only as
// far as the pose and the wheels agree on it: a state estimator's jitter moves the pose by centimetres
// while the wheels stand, and wheels slipping against a wall turn while the pose stays.

#include <cstdint>
#include <optional>

#include "common/geometry/pose2.hpp"
#include "executive/modes/cycle.hpp"
#include "executive/modes/odometer.hpp"

namespace ifar::executive {

class StandstillWatch {
 public:
  /// Moving more than `still_distance_m` or turning more than `still_turn_rad` is motion; standing
  /// longer than `timeout_s` without it is standing still.
  StandstillWatch(double still_distance_m, double still_turn_rad, double timeout_s);

  /// Restarts the watch at the view's pose (and wheel track), now.
  void anchor(const CycleView& view);
  /// True when the vehicle has not moved since the anchor for longer than the timeout; re-anchors when
  /// it has.
  bool standingStill(const CycleView& view);

 private:
  double still_distance_m_;
  double still_turn_rad_;
  double timeout_s_;
  geometry::Pose2 anchor_;
  std::optional<WheelTrack> anchor_wheels_;
  std::int64_t anchor_us_ = 0;
};

}  // namespace ifar::executive
