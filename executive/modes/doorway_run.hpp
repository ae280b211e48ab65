#pragma once
// Driving a door barely wider than the vehicle as a straight run (executive/doorway): to the run's start,
// square to the door, along the run to its end; given up (and the door left to the follower for a while)
// when it takes too long or stands still.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "executive/doorway/doorway.hpp"
#include "executive/follower/follower.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/modes/collision_guard.hpp"
#include "executive/modes/cycle.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/inputs.hpp"
#include "executive/modes/standstill_watch.hpp"
#include "executive/pusher/approach.hpp"

namespace ifar::executive {

class DoorwayRun {
 public:
  /// `settings.follower.footprint` must be the vehicle's.
  DoorwayRun(const ExecutiveSettings& settings, const DifferentialDrive& drive);

  /// The first doorway on `ahead` (the vehicle's position, then the path up to a push) worth a run: not
  /// given up lately, and with `goal` neither in the door nor on its run (that is the follower's to reach).
  std::optional<Doorway> find(common::Span<const geometry::Point> ahead, const geometry::Point& goal,
                              const CycleView& view) const;

  void start(const Doorway& doorway, const CycleView& view);

  enum class Progress { Driving, Through, GivenUp };
  struct Step {
    Progress progress = Progress::Driving;
    std::string given_up;  ///< GivenUp: the door and why, for the reason
  };
  /// One cycle of the run started last: fills `request` while Driving (guarded once off the follower's
  /// leg to the run's start).
  Step step(const CycleView& view, const CollisionGuard& guard, MotionRequest& request);

  /// Where the run ends.
  geometry::Point runEnd() const { return doorway_->runEnd(settings_); }
  /// True when a run under way should go on along `path` (a new plan): the vehicle is already in the
  /// door, along the lane (stopping there leaves it wedged between the posts), or the path still goes
  /// through the door.
  bool keepsGoingFor(const Path& path) const;
  /// After the run: true for a waypoint at the door's posts or on the run, now behind the vehicle.
  bool leftBehind(const geometry::Point& waypoint) const;
  /// The run is over.
  void finish() { doorway_.reset(); }

 private:
  bool crosses(const Path& path) const;

  DoorwaySettings settings_;
  ApproachSettings run_settings_;
  FollowerSettings follower_;
  DifferentialDrive drive_;
  double goal_tolerance_m_;
  double waypoint_tolerance_m_;
  std::optional<Doorway> doorway_;  // being driven through
  Approach run_;                    // to the run's start, square to the door, along the run
  std::int64_t started_us_ = 0;
  StandstillWatch standstill_;
  /// Doorways whose run was given up, by centre, and until when (microseconds) they are left to the
  /// follower.
  std::vector<std::pair<geometry::Point, std::int64_t>> given_up_;
};

}  // namespace ifar::executive
