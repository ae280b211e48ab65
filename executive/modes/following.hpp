#pragma once
// Following the path toward the current waypoint with the collision-free local planner, and telling when
// that gets nowhere (the arcs dither left and right, wedged at a door or beside a wall with the target
// behind): a stall, which the mode machine answers with the stall recovery.

#include <cstdint>

#include "common/geometry/point.hpp"
#include "executive/follower/follower.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/modes/cycle.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/standstill_watch.hpp"

namespace ifar::executive {

class Following {
 public:
  /// `settings.follower.footprint` must be the vehicle's.
  Following(const ExecutiveSettings& settings, const DifferentialDrive& drive);

  struct Step {
    FollowerResult result;
    bool stalled = false;  ///< following has got nowhere for stall_timeout_s
  };

  /// One cycle toward `target`, the goal when `to_goal` (then the follower stops within the goal
  /// tolerance, else it passes within the waypoint tolerance). Hemmed in at about the clearance (along a
  /// wall every arc dips a little below it; turning swings a corner closer), or lined up with a door
  /// barely wider than the vehicle plus twice the clearance (only turning on the spot is left), the
  /// follower retries with the clearance lowered to the guard's.
  Step step(const CycleView& view, const geometry::Point& target, bool to_goal);

  /// The next step starts a fresh stall clock (after another task, or a stall's recovery).
  void restart() { watching_ = false; }

 private:
  FollowerSettings follower_;
  DifferentialDrive drive_;
  double waypoint_tolerance_m_;
  double goal_tolerance_m_;
  double squeeze_clearance_m_;
  std::int64_t resume_after_us_;
  StandstillWatch stall_watch_;
  bool watching_ = false;          // false: the stall clock starts at the next step
  std::int64_t last_step_us_ = 0;  // the last cycle that followed
};

}  // namespace ifar::executive
