#pragma once
// Backing off: after following got nowhere for stall_timeout_s (wedged in a door, dithering beside a
// wall), drive pusher.release_m straight back (or ahead, when there is less room behind), or reverse along
// the follower's cost-to-go when the way on is behind, then turn on the spot to face the way on; or, after
// a push given up, reverse pusher.release_m away from the object (the follower only plans forward, so with
// the object on the bumper it would be boxed in). Every command is guarded; the mode machine follows again
// afterwards.

#include <cstdint>
#include <optional>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "executive/follower/follower.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/modes/collision_guard.hpp"
#include "executive/modes/cycle.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/path_progress.hpp"
#include "executive/modes/standstill_watch.hpp"

namespace ifar::executive {

class StallRecovery {
 public:
  /// `settings.follower.footprint` must be the vehicle's.
  StallRecovery(const ExecutiveSettings& settings, const DifferentialDrive& drive);

  /// Following got nowhere: escape straight or reversing, turn to the way on.
  void beginStallEscape();
  /// A push was given up and a new path came: reverse away from the object first.
  void beginBackingAway() { start_.reset(); }
  /// True while it escapes a stall (not backing away from an object).
  bool afterStall() const { return after_stall_; }

  enum class Next {
    Continue,         ///< `request` holds this cycle's command
    FollowNow,        ///< done: follow again this cycle
    FollowNextCycle,  ///< hemmed in (every way guarded): `request` stops; follow again from here
  };
  /// One cycle. `way_on`: the waypoint following heads for; `away_obstacles`: the points to back away
  /// from an object among (without the object's own); `object_id`: that object, for the reason.
  Next step(const CycleView& view, const std::optional<WayOn>& way_on,
            common::Span<const geometry::Point> away_obstacles, std::int64_t object_id,
            const CollisionGuard& guard, MotionRequest& request);

 private:
  /// The heading the follower's cost-to-go wants at the pose, when it is off by more than the turn
  /// tolerance (a door entered at a slant wedges the corners on its posts).
  std::optional<double> turnHeading(const CycleView& view, const std::optional<WayOn>& way_on) const;
  /// Reversing along the follower's cost-to-go toward the waypoint, when it lies behind the vehicle and
  /// a reversing arc gets closer to it; none otherwise.
  std::optional<FollowerResult> reverseToward(const CycleView& view,
                                              const std::optional<WayOn>& way_on) const;
  /// Turning on the spot to the chosen heading, while it is off and the turn has time left. True when
  /// `request` turns (the guard let it).
  bool turnToWayOn(const CycleView& view, const CollisionGuard& guard, MotionRequest& request) const;
  /// The stall escape proper: reversing along the cost-to-go, or straight back or ahead.
  Next escape(const CycleView& view, const std::optional<WayOn>& way_on, double travelled,
              const CollisionGuard& guard, MotionRequest& request);
  /// Straight at `linear`, or on an arc when straight is guarded (turning first toward the way on).
  void guardedEscape(const CycleView& view, const std::optional<WayOn>& way_on, double linear,
                     common::Span<const geometry::Point> obstacles, const CollisionGuard& guard,
                     MotionRequest& request) const;

  StallRecoverySettings settings_;
  FollowerSettings follower_;
  DifferentialDrive drive_;
  double stall_timeout_s_;
  double release_m_;
  double reverse_speed_;
  double squeeze_clearance_m_;
  double max_turn_rate_;
  double turn_gain_;

  std::optional<geometry::Point> start_;  // where backing off began (set on its first step)
  bool after_stall_ = false;              // escaping a stall, not backing away after a push
  double escape_sign_ = 0.0;              // -1 reversing, +1 driving ahead, 0 not chosen yet
  bool reversing_ = false;                // reversing along the cost-to-go to a waypoint behind
  std::optional<double> turn_heading_;    // after the straight escape: turning on the spot to this ...
  std::int64_t turn_since_us_ = 0;        // ... since then
  // The straight escape standing still (wedged, its wheels slipping against what the guard does not see)
  // as long as an approach or a push may: the other way once, then follow again from here.
  StandstillWatch escape_standstill_;
  bool escape_flipped_ = false;
};

}  // namespace ifar::executive
