#include "executive/modes/stall_recovery.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

StallRecovery::StallRecovery(const ExecutiveSettings& settings, const DifferentialDrive& drive)
    : settings_(settings.stall_recovery),
      follower_(settings.follower),
      drive_(drive),
      stall_timeout_s_(settings.stall_timeout_s),
      release_m_(settings.pusher.release_m),
      reverse_speed_(settings.pusher.reverse_speed),
      squeeze_clearance_m_(settings.pushed_object.guard_clearance_m),
      max_turn_rate_(settings.approach.control.max_angular_velocity),
      turn_gain_(settings.approach.control.angular_gain),
      escape_standstill_(settings.stall_recovery.still_distance_m, settings.stall_recovery.still_turn_rad,
                         settings.stall_recovery.standstill_timeout_s)
{
}

void StallRecovery::beginStallEscape()
{
  after_stall_ = true;
  escape_sign_ = 0.0;
  reversing_ = false;
  turn_heading_.reset();
  start_.reset();
  escape_flipped_ = false;
}

StallRecovery::Next StallRecovery::step(const CycleView& view, const std::optional<WayOn>& way_on,
                                        common::Span<const geometry::Point> away_obstacles,
                                        std::int64_t object_id, const CollisionGuard& guard,
                                        MotionRequest& request)
{
  if (!start_) {
    start_ = view.pose.position();
  }
  const double travelled = (view.pose.position() - *start_).norm();
  bool escape_further = false;
  if (after_stall_ && travelled >= release_m_ && !turn_heading_) {
    // Face the way the cost-to-go falls before following again, when that takes a turn on the spot; while
    // the turn is not free, go on straight a little further.
    const std::optional<double> wanted = turnHeading(view, way_on);
    if (wanted && guard.freeTurn(view.pose, *wanted, view.obstacles)) {
      turn_heading_ = wanted;
      turn_since_us_ = view.now_us;
    } else if (wanted &&
               travelled < (reversing_ ? settings_.reversing_m : settings_.straight_releases * release_m_)) {
      escape_further = true;
    }
  }
  if (turn_heading_ && turnToWayOn(view, guard, request)) {
    return Next::Continue;
  }
  if (travelled >= release_m_ && !escape_further) {
    after_stall_ = false;
    escape_sign_ = 0.0;
    reversing_ = false;
    turn_heading_.reset();
    return Next::FollowNow;
  }
  if (after_stall_) {
    return escape(view, way_on, travelled, guard, request);
  }
  request.reason =
      fmt::format("backing away from object {} before following the new path: {:.2f} of {:.2f} m", object_id,
                  travelled, release_m_);
  guardedEscape(view, way_on, -reverse_speed_, away_obstacles, guard, request);
  // Hemmed in behind: follow the new path from here (its stall recovery tries ahead too) rather than wait.
  return request.command.isZero() ? Next::FollowNextCycle : Next::Continue;
}

bool StallRecovery::turnToWayOn(const CycleView& view, const CollisionGuard& guard,
                                MotionRequest& request) const
{
  const double error = wrapToPi(*turn_heading_ - view.pose.heading);
  const double turned_s = static_cast<double>(view.now_us - turn_since_us_) * 1e-6;
  if (!(std::abs(error) > settings_.turn_tolerance_rad && turned_s < settings_.turn_timeout_s)) {
    return false;
  }
  const double rate = std::min(max_turn_rate_, turn_gain_ * std::abs(error));
  request.command = {0.0, std::copysign(rate, error)};
  request.reason =
      fmt::format("stalled for {:.1f} s: turning on the spot to face the way on, {:.0f} deg to go",
                  stall_timeout_s_, std::abs(error) * 180.0 / kPi);
  guard.stop(view.pose, view.obstacles, request);
  return !request.command.isZero();
}

StallRecovery::Next StallRecovery::escape(const CycleView& view, const std::optional<WayOn>& way_on,
                                          double travelled, const CollisionGuard& guard,
                                          MotionRequest& request)
{
  // Straight back, or straight ahead when the back is nearer a wall (wedged by a door post while
  // turning); chosen once, kept until the distance is done. Reversing along the cost-to-go is planned
  // once per cycle: it builds the follower's cost-to-go and samples the whole fan.
  std::optional<FollowerResult> reversing;
  if (escape_sign_ == 0.0) {
    const double back = guard.freeStraightDistance(view.pose, -1.0, view.obstacles, release_m_);
    const double ahead = guard.freeStraightDistance(view.pose, 1.0, view.obstacles, release_m_);
    reversing = reverseToward(view, way_on);
    reversing_ = reversing.has_value();
    escape_sign_ = reversing_ || back >= ahead ? -1.0 : 1.0;
    escape_standstill_.anchor(view);
  } else if (reversing_) {
    reversing = reverseToward(view, way_on);
  }
  if (reversing_) {
    if (reversing) {
      request.command = reversing->command;
      request.reason = fmt::format("stalled for {:.1f} s: the way on is behind, {:.2f} m reversed: {}",
                                   stall_timeout_s_, travelled, reversing->reason);
      guard.stop(view.pose, view.obstacles, request);
      if (!request.command.isZero()) {
        return Next::Continue;
      }
    }
    // Reversing got nowhere or was guarded: straight back from here, as without a waypoint behind.
    reversing_ = false;
  }
  if (escape_standstill_.standingStill(view)) {
    if (escape_flipped_) {
      after_stall_ = false;
      escape_sign_ = 0.0;
      request.command = {0.0, 0.0};
      request.reason =
          fmt::format("stalled for {:.1f} s: held both ways, following again from here", stall_timeout_s_);
      return Next::FollowNextCycle;
    }
    escape_flipped_ = true;
    escape_sign_ = -escape_sign_;
    start_ = view.pose.position();
    travelled = 0.0;
    escape_standstill_.anchor(view);
  }
  request.reason =
      fmt::format("stalled for {:.1f} s: {} before following again: {:.2f} of {:.2f} m", stall_timeout_s_,
                  escape_sign_ < 0.0 ? "backing up" : "driving ahead", travelled, release_m_);
  guardedEscape(view, way_on, escape_sign_ * reverse_speed_, view.obstacles, guard, request);
  if (!request.command.isZero()) {
    return Next::Continue;
  }
  // Hemmed in (the chosen way closed): follow again from here rather than wait.
  after_stall_ = false;
  escape_sign_ = 0.0;
  reversing_ = false;
  return Next::FollowNextCycle;
}

void StallRecovery::guardedEscape(const CycleView& view, const std::optional<WayOn>& way_on, double linear,
                                  common::Span<const geometry::Point> obstacles, const CollisionGuard& guard,
                                  MotionRequest& request) const
{
  const double turn_rates[] = {settings_.gentle_arc_fraction * max_turn_rate_, max_turn_rate_};
  const auto first_turn_sign = [&]() {
    const std::optional<double> wanted = turnHeading(view, way_on);
    return wanted && wrapToPi(*wanted - view.pose.heading) < 0.0 ? -1.0 : 1.0;
  };
  guard.escape(view.pose, linear, turn_rates, first_turn_sign, obstacles, request);
}

std::optional<double> StallRecovery::turnHeading(const CycleView& view,
                                                 const std::optional<WayOn>& way_on) const
{
  if (!way_on) {
    return std::nullopt;
  }
  const std::optional<double> heading =
      facingDirection(view.pose, way_on->position, way_on->is_goal, view.obstacles, follower_, drive_);
  if (!heading || std::abs(wrapToPi(*heading - view.pose.heading)) <= settings_.turn_tolerance_rad) {
    return std::nullopt;
  }
  return heading;
}

std::optional<FollowerResult> StallRecovery::reverseToward(const CycleView& view,
                                                           const std::optional<WayOn>& way_on) const
{
  if (!way_on) {
    return std::nullopt;
  }
  const geometry::Point offset = way_on->position - view.pose.position();
  const double bearing = std::atan2(offset.y(), offset.x());
  if (std::abs(wrapToPi(bearing - view.pose.heading)) <= kPi / 2.0) {
    return std::nullopt;
  }
  FollowerResult result = followReversing(view.pose, way_on->position, view.obstacles, follower_,
                                          squeeze_clearance_m_, reverse_speed_, drive_);
  if (result.status != FollowerStatus::Moving || result.progress_m <= settings_.reversing_progress_m) {
    return std::nullopt;
  }
  return result;
}

}  // namespace ifar::executive
