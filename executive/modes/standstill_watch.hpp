#pragma once
// Tells when the vehicle has got nowhere for a while: neither moved nor turned enough since it was last
// anchored (by the caller, or by itself whenever it moves).

#include <cstdint>

#include "common/geometry/pose2.hpp"

namespace ifar::executive {

class StandstillWatch {
 public:
  /// Moving more than `still_distance_m` or turning more than `still_turn_rad` is motion; standing
  /// longer than `timeout_s` without it is standing still.
  StandstillWatch(double still_distance_m, double still_turn_rad, double timeout_s);

  /// Restarts the watch at `pose`, now.
  void anchor(const geometry::Pose2& pose, std::int64_t now_us);
  /// True when the vehicle has not moved since the anchor for longer than the timeout; re-anchors at
  /// `pose` when it has.
  bool standingStill(const geometry::Pose2& pose, std::int64_t now_us);

 private:
  double still_distance_m_;
  double still_turn_rad_;
  double timeout_s_;
  geometry::Pose2 anchor_;
  std::int64_t anchor_us_ = 0;
};

}  // namespace ifar::executive
