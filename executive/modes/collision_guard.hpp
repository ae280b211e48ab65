#pragma once
// The guard on the commands the follower does not plan (aligning, creeping, pushing, backing off, turning
// on the spot, doorway runs): the footprint moved along a command must not come closer than the guard
// clearance to a point it is closing in on. Moving away from something already close is always allowed,
// so a vehicle that ended up close (after a push) can leave. Const: the same question, the same answer.

#include <functional>
#include <optional>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "common/span.hpp"
#include "executive/follower/footprint.hpp"
#include "executive/kinematics/velocity_command.hpp"
#include "executive/modes/cycle.hpp"

namespace ifar::executive {

class CollisionGuard {
 public:
  /// `clearance_m`: the least distance kept; `horizon_s`: how far ahead a command is checked, every
  /// `time_step_s` (at most the horizon).
  CollisionGuard(const Footprint& footprint, double clearance_m, double horizon_s, double time_step_s);

  /// The first point that `command`, driven from `pose` for the horizon, brings the footprint closer than
  /// the clearance to while closing in on it; none when the command is free (or zero).
  std::optional<geometry::Point> pointInTheWay(const geometry::Pose2& pose, const VelocityCommand& command,
                                               common::Span<const geometry::Point> obstacles) const;

  /// Zeroes `request.command` when a point is in its way, and says so at the end of its reason. True
  /// when it stopped it.
  bool stop(const geometry::Pose2& pose, common::Span<const geometry::Point> obstacles,
            MotionRequest& request) const;

  /// Drives straight at `linear` m/s, or, when that is stopped, along the first free arc of the same
  /// speed: at each rate of `turn_rates` in turn, turning first the way `first_turn_sign()` says (+1 left,
  /// -1 right; asked only when straight is stopped), then the other way. The reason says which arc; the
  /// command is zero (reason: what stopped straight) when every one is stopped.
  void escape(const geometry::Pose2& pose, double linear, common::Span<const double> turn_rates,
              const std::function<double()>& first_turn_sign, common::Span<const geometry::Point> obstacles,
              MotionRequest& request) const;

  /// How far (up to `limit_m`) the vehicle can drive straight from `pose` (`sign` -1 back, +1 ahead)
  /// without its footprint coming within the clearance of a point it is not already that close to.
  double freeStraightDistance(const geometry::Pose2& pose, double sign,
                              common::Span<const geometry::Point> obstacles, double limit_m) const;

  /// True when turning on the spot from `pose` to `heading` keeps the footprint out of the clearance (plus
  /// `margin_m`) of every point it is not already that close to.
  bool freeTurn(const geometry::Pose2& pose, double heading, common::Span<const geometry::Point> obstacles,
                double margin_m = 0.0) const;

 private:
  Footprint footprint_;
  double clearance_m_;
  double horizon_s_;
  double time_step_s_;
};

}  // namespace ifar::executive
