#pragma once
// Dead reckoning of wheel odometry between control cycles, so that the parts can ask what the wheels did
// since a moment of their choosing (how far they rolled, how far they turned) and compare it with the
// pose: motion counts only where both agree.

#include <cstdint>
#include <optional>

#include "common/geometry/pose2.hpp"
#include "executive/modes/inputs.hpp"

namespace ifar::executive {

/// Where the wheels have taken the vehicle, in the odometry's own frame.
struct WheelTrack {
  geometry::Pose2 pose;   ///< dead-reckoned from the first fresh reading of this segment
  double travel_m = 0.0;  ///< signed distance rolled forward (backward negative), over every segment
  /// Counts the interruptions (odometry absent or stale): tracks of different segments do not compare.
  std::int64_t segment = 0;
};

class Odometer {
 public:
  /// Integrates the body velocity over the time since the last call (the mean of the last and this
  /// reading). `reading` empty (absent, stale, flagged invalid) interrupts the track; it resumes from
  /// the next fresh reading without integrating the gap.
  void update(std::int64_t now_us, const std::optional<OdometryReading>& reading);
  /// The track while odometry is fresh; empty otherwise.
  std::optional<WheelTrack> track() const;

 private:
  WheelTrack track_;
  bool fresh_ = false;
  OdometryReading last_;
  std::int64_t last_us_ = 0;
};

/// Distance and turn between two tracks of one segment; empty when they are of different segments.
struct WheelMotion {
  double distance_m = 0.0;  ///< straight-line distance between the two dead-reckoned poses
  double turn_rad = 0.0;    ///< absolute heading change
  double travel_m = 0.0;    ///< signed distance rolled
};
std::optional<WheelMotion> wheelMotion(const WheelTrack& from, const WheelTrack& to);

}  // namespace ifar::executive
