#pragma once
// Everything the executive is tuned by, from config/executive.yaml, plus the vehicle's outline.

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "common/vehicle.hpp"
#include "executive/affordance/tactile_monitor.hpp"
#include "executive/doorway/doorway.hpp"
#include "executive/follower/follower.hpp"
#include "executive/follower/footprint.hpp"
#include "executive/modes/progress_monitor.hpp"
#include "executive/pusher/approach.hpp"
#include "executive/pusher/push_tracker.hpp"

namespace ifar::executive {

/// An input older than its threshold is stale: the vehicle stops within one cycle.
struct StaleThresholds {
  double pose_s = 0.1;
  double path_s = 1.0;
  double force_s = 0.1;
  double motor_s = 0.3;
  double obstacles_s = 0.5;  ///< older obstacle points are not used (the status says so)
  double odometry_s = 0.1;   ///< older wheel odometry is not used: motion is judged on the pose alone
};

/// While approaching and pushing, the pushed object is no obstacle, but everything else still is.
struct PushedObjectSettings {
  /// Returns within this distance of the object's expected centroid path (from its position at first
  /// contact through every primitive's expected end) or of its observed centroid belong to the object.
  double radius_m = 0.8;
  /// Any other return closer than this to the footprint along the command stops the vehicle (creep,
  /// push, back-off; the collision-free legs keep the follower's clearance). Also the least clearance
  /// the executive lets a blocked follower squeeze down to.
  double guard_clearance_m = 0.05;
  double guard_horizon_s = 0.5;  ///< how far ahead the command is checked, seconds
};

/// Where a gap too narrow for the vehicle is reported as a blocked passage on sight.
enum class GapReportScope { Off, NearPushedObjects, Everywhere };

/// Telling when the vehicle gets nowhere, and the way out after following stalled: back off straight (or
/// reversing along the cost-to-go to a waypoint behind), turn on the spot to face the way on, follow again.
struct StallRecoverySettings {
  /// Moving less than this and turning less than still_turn_rad is getting nowhere: the follower dithering
  /// a few degrees left and right, wedged in a door, moves and turns less.
  double still_distance_m = 0.1;
  double still_turn_rad = 0.3;
  /// Following again after a pause longer than this (a stop, another task) starts a fresh stall clock:
  /// the time spent doing something else is not time spent stalled.
  double resume_after_s = 0.2;
  /// A doorway run, an approach or a push standing still this long is given up. Longer than
  /// stall_timeout_s: giving up a push costs an affordance report and a replan.
  double standstill_timeout_s = 3.0;
  /// After the straight escape, the vehicle turns on the spot to face the way the follower's cost-to-go
  /// falls when that is more than this off its heading (a door entered at a slant wedges the corners on
  /// its posts, and following again repeats the slant) ...
  double turn_tolerance_rad = 0.2;
  double turn_timeout_s = 5.0;  ///< ... for at most this long
  /// While that turn is not free, the straight escape goes on, up to this many pusher.release_m.
  double straight_releases = 3.0;
  /// With the waypoint behind the vehicle, the escape reverses along the cost-to-go instead of straight
  /// back, up to this far: out of a dead end too narrow to turn in, back to where it widens ...
  double reversing_m = 2.0;
  double reversing_progress_m = 0.01;  ///< ... when a reversing arc lowers the cost-to-go by more than this
  /// When the guard stops a straight escape, arcs of the same speed are tried at this fraction of
  /// control.max_angular_velocity, then at all of it: wedged at a slant, straight back closes in on a
  /// wall that an arc clears.
  double gentle_arc_fraction = 0.5;
};

struct ExecutiveSettings {
  StaleThresholds stale;
  double waypoint_tolerance_m = 0.4;  ///< an intermediate waypoint counts as passed within this
  /// ... and within this when the vehicle stands beyond it, on the next leg's side of the line through it
  /// square to that leg (a door post's inflated corner is closer to the post than the vehicle can get).
  double waypoint_pass_radius_m = 1.0;
  double goal_tolerance_m = 0.3;  ///< the goal counts as reached within this
  double push_switch_radius_m =
      1.5;  ///< r of Algorithm 2: switch to pushing this close to a topological waypoint
  /// A new plan to the same goal within goal_tolerance_m + this of the vehicle keeps it arrived: it coasts
  /// a few centimetres after stopping.
  double arrived_hold_m = 0.1;
  double replan_timeout_s = 10.0;  ///< waiting longer for a replanned path stops the vehicle
  double stall_timeout_s = 1.5;    ///< following without moving this long: back off and try again
  StallRecoverySettings stall_recovery;
  ProgressSettings progress;  ///< the loop's progress toward the goal, and when it escalates
  /// This many stalls at one site toward one waypoint report the passage as blocked (0: never).
  int blocked_passage_stalls = 3;
  /// Stalls within this distance of the first one of a series, toward path points this close to each
  /// other, are one site; a waypoint within waypoint_pass_radius_m counts as passed on either side where
  /// following stalls again this close to its last stall; a gap reported on sight this close to the last
  /// one is the same gap.
  double stall_site_radius_m = 1.0;
  /// A blocked passage is reported toward the path point this far ahead (along the path), not the
  /// waypoint: the planner seals beyond the vehicle's inflation, so a waypoint a step ahead leaves it no
  /// room, and one at the end of a long leg lets the seal land anywhere along it.
  double blocked_passage_ahead_m = 2.5;
  /// A gap on the path ahead (within doorway.look_ahead_m) narrower than the vehicle plus twice
  /// doorway.min_clearance_m is reported as a blocked passage on sight, without stalling in it first:
  /// never, only beside an object this executive pushed (within pushed_object.radius_m of where the
  /// push left it), or everywhere.
  GapReportScope blocked_passage_on_sight = GapReportScope::NearPushedObjects;
  double gap_report_repeat_s = 2.0;  ///< the same gap (within 1 m) is reported again after this long
  /// A gap seen on sight is reported toward the path point this far beyond it: the planner seals the
  /// narrowest free point between the vehicle and that point, and a farther one let the seal land at
  /// another gap on a straight line cutting corners.
  double gap_report_beyond_m = 1.0;
  /// Where the last this many pushes left their objects (for near_pushed_objects): only recent pushes
  /// matter to the lanes the vehicle is about to drive.
  int pushed_objects_remembered = 8;
  /// Between two cycles the speeds may grow by at most this long's acceleration, however late the second
  /// cycle comes (a hiccup of the caller must not allow a jump).
  double max_cycle_gap_s = 0.2;
  /// Vehicle reference point (the pose) to the bumper face; the rest of the vehicle length is behind.
  /// The Executive builds the follower's footprint from this and the vehicle's length and width.
  double reference_to_bumper_m = 0.45;
  FollowerSettings follower;
  DoorwaySettings doorway;
  ApproachSettings approach;
  PushTrackerSettings pusher;
  TactileSettings tactile;
  PushedObjectSettings pushed_object;
};

/// executive.yaml's keys but the `obstacles:` section's, every one required.
const common::ParameterTable<ExecutiveSettings>& executiveParameters();

/// Reads every key of executive.yaml (all required; numbers must be positive unless noted) and rejects
/// unknown ones. Throws common::ConfigError naming the key. The `obstacles:` section belongs to
/// loadObstacleSettings (executive/obstacles) and is left for it.
ExecutiveSettings loadExecutiveSettings(const common::ConfigNode& node);

/// The vehicle's outline for the follower: `reference_to_bumper_m` ahead of the pose, the rest of
/// `length_m` behind, `width_m` wide. Throws std::invalid_argument when the bumper distance is not within
/// (0, length_m].
Footprint vehicleFootprint(const common::VehicleSettings& vehicle, double reference_to_bumper_m);

}  // namespace ifar::executive
