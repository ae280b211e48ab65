#include "executive/modes/following.hpp"

#include <cmath>

namespace ifar::executive {

Following::Following(const ExecutiveSettings& settings, const DifferentialDrive& drive)
    : follower_(settings.follower),
      drive_(drive),
      waypoint_tolerance_m_(settings.waypoint_tolerance_m),
      goal_tolerance_m_(settings.goal_tolerance_m),
      squeeze_clearance_m_(settings.pushed_object.guard_clearance_m),
      resume_after_us_(std::llround(settings.stall_recovery.resume_after_s * 1e6)),
      stall_watch_(settings.stall_recovery.still_distance_m, settings.stall_recovery.still_turn_rad,
                   settings.stall_timeout_s)
{
}

Following::Step Following::step(const CycleView& view, const geometry::Point& target, bool to_goal)
{
  // The follower stops at its target: at the goal that must be within the arrival tolerance, or the
  // vehicle would halt between the two tolerances and never arrive.
  FollowerSettings follower = follower_;
  follower.goal_tolerance_m = to_goal ? goal_tolerance_m_ : waypoint_tolerance_m_;
  Step step;
  step.result =
      followSqueezing(view.pose, target, to_goal, view.obstacles, follower, squeeze_clearance_m_, drive_);
  const bool resumed = view.now_us - last_step_us_ > resume_after_us_;
  last_step_us_ = view.now_us;
  const bool trying =
      step.result.status == FollowerStatus::Moving || step.result.status == FollowerStatus::Blocked;
  if (!watching_ || resumed || !trying) {
    stall_watch_.anchor(view);
    watching_ = true;
  } else {
    step.stalled = stall_watch_.standingStill(view);
  }
  return step;
}

}  // namespace ifar::executive
