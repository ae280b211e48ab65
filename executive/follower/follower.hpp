#pragma once
// The collision-free local planner used between waypoints (paper section VII.B, "CollisionFreePlanner"):
// samples a fan of constant (v, omega) arcs over a short horizon, drops every arc whose footprint comes
// closer than the clearance to an obstacle point, and picks the free arc that best lowers the cost-to-go
// to the target (a navigation function over a local grid, so obstacles are driven around and doors are
// taken through their middle), faces the way that cost-to-go falls and keeps clear. A pure function: same
// inputs, same command.

#include <optional>
#include <string>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "common/span.hpp"
#include "executive/follower/footprint.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/kinematics/velocity_command.hpp"

namespace ifar::executive {

struct FollowerSettings {
  double horizon_s = 2.0;        ///< how far ahead each arc is checked, seconds
  double time_step_s = 0.1;      ///< spacing of the footprint checks along an arc, seconds
  int linear_samples = 5;        ///< forward speeds max/n .. max, plus turning on the spot
  int angular_samples = 15;      ///< angular speeds spread evenly over [-max, max]
  double clearance_m = 0.15;     ///< margin kept between the footprint and obstacle points
  double clearance_cap_m = 0.5;  ///< clearance beyond this earns no more score
  double progress_weight = 1.0;
  double heading_weight = 0.2;
  double clearance_weight = 0.1;
  double goal_tolerance_m = 0.3;  ///< the target counts as reached within this distance
  /// Approaching a target to stop at, the vehicle brakes from top speed over this distance (to the
  /// tolerance's edge) at constant deceleration: top speed x sqrt(remaining / this).
  double slow_down_distance_m = 1.0;
  double max_linear_velocity = 0.8;  ///< m/s; the vehicle's own limit applies too
  double cell_size_m = 0.25;         ///< obstacle bucket size
  double navigation_range_m = 6.0;   ///< half-size limit of the cost-to-go window around the vehicle
  double navigation_cell_m = 0.2;    ///< cost-to-go cell size
  /// Cost-to-go cells within half width + clearance_cap_m of an obstacle cost up to (1 + this) x their
  /// length, so the vehicle keeps to the middle of doors and corridors rather than the wall-hugging path.
  double navigation_proximity_weight = 3.0;
  /// The cost-to-go is sampled on a circle this wide around a point for the way it falls (the way to
  /// face); a target closer than this is faced itself, since the circle reaches past it.
  double descent_radius_m = 0.5;
  /// Facing this far or more off the way the cost-to-go falls, the vehicle turns on the spot; from a
  /// third of this on, its forward speed cap falls linearly from top speed to 0. A sharp turn of the path
  /// is then a pivot, not a loop as wide as the fastest arc's radius. 0: no cap (the shipped setting: see
  /// docs/executive.md for what the cap costs in time).
  double turn_in_place_rad = 0.0;
  Footprint footprint;
};

enum class FollowerStatus { Moving, Arrived, Blocked, InvalidInput };

const char* followerStatusName(FollowerStatus status);

struct FollowerResult {
  VelocityCommand command;
  FollowerStatus status = FollowerStatus::Blocked;
  std::string reason;
  double clearance_m = 0.0;  ///< of the chosen arc (or of the current pose when not moving)
  double progress_m = 0.0;   ///< how much the chosen arc lowers the cost-to-go; 0 when turning on the spot
  int free_arcs = 0;
  int arcs = 0;
};

/// One planning cycle. `obstacles` are world-frame points (the latest local obstacle set);
/// `stop_at_target` slows down near the target (the goal), otherwise the vehicle passes through it.
FollowerResult follow(const geometry::Pose2& pose, const geometry::Point& target, bool stop_at_target,
                      common::Span<const geometry::Point> obstacles, const FollowerSettings& settings,
                      const DifferentialDrive& drive);

/// follow(), and when that is stuck (blocked, or moving without progress: hemmed in along a wall at about
/// the clearance, or lined up with a door only the clearance wider than the vehicle) once more with the
/// clearance lowered to `squeeze_clearance_m`, taking the retry when it moves (blocked) or gets further;
/// its reason then ends with "(squeezing: clearance x m)".
FollowerResult followSqueezing(const geometry::Pose2& pose, const geometry::Point& target,
                               bool stop_at_target, common::Span<const geometry::Point> obstacles,
                               const FollowerSettings& settings, double squeeze_clearance_m,
                               const DifferentialDrive& drive);

/// followSqueezing() driving rear first at up to `reverse_speed`: the same fan of arcs for the vehicle
/// turned round (pose heading + pi, front and rear swapped), with the chosen command's linear velocity
/// negated. For a target behind a vehicle that has no room to turn on the spot (wedged facing into a
/// dead end), which forward arcs can only drive further from it.
FollowerResult followReversing(const geometry::Pose2& pose, const geometry::Point& target,
                               common::Span<const geometry::Point> obstacles,
                               const FollowerSettings& settings, double squeeze_clearance_m,
                               double reverse_speed, const DifferentialDrive& drive);

/// The heading the follower's cost-to-go falls along at `pose` toward `target` (the bearing of the target
/// itself when it is near): the way to face before driving on. None when the field has no way there.
std::optional<double> facingDirection(const geometry::Pose2& pose, const geometry::Point& target,
                                      bool stop_at_target, common::Span<const geometry::Point> obstacles,
                                      const FollowerSettings& settings, const DifferentialDrive& drive);

}  // namespace ifar::executive
