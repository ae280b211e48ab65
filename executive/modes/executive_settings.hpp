#pragma once
// Everything the executive is tuned by, from config/executive.yaml, plus the vehicle's outline.

#include "common/config.hpp"
#include "common/vehicle.hpp"
#include "executive/affordance/tactile_monitor.hpp"
#include "executive/doorway/doorway.hpp"
#include "executive/follower/follower.hpp"
#include "executive/follower/footprint.hpp"
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

struct ExecutiveSettings {
  StaleThresholds stale;
  double waypoint_tolerance_m = 0.4;  ///< an intermediate waypoint counts as passed within this
  /// ... and within this when the vehicle stands beyond it, on the next leg's side of the line through it
  /// square to that leg (a door post's inflated corner is closer to the post than the vehicle can get).
  double waypoint_pass_radius_m = 1.0;
  double goal_tolerance_m = 0.3;  ///< the goal counts as reached within this
  double push_switch_radius_m =
      1.5;  ///< r of Algorithm 2: switch to pushing this close to a topological waypoint
  double replan_timeout_s = 10.0;  ///< waiting longer for a replanned path stops the vehicle
  double stall_timeout_s = 1.5;    ///< following without moving this long: back off and try again
  /// This many stalls at one site toward one waypoint report the passage as blocked (0: never).
  int blocked_passage_stalls = 3;
  /// A gap on the path ahead (within doorway.look_ahead_m) narrower than the vehicle plus twice
  /// doorway.min_clearance_m is reported as a blocked passage on sight, without stalling in it first:
  /// never, only beside an object this executive pushed (within pushed_object.radius_m of where the
  /// push left it), or everywhere.
  GapReportScope blocked_passage_on_sight = GapReportScope::NearPushedObjects;
  double gap_report_repeat_s = 2.0;  ///< the same gap (within 1 m) is reported again after this long
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

/// Reads every key of executive.yaml (all required; numbers must be positive unless noted) and rejects
/// unknown ones. Throws common::ConfigError naming the key. The `obstacles:` section belongs to
/// loadObstacleSettings (executive/obstacles) and is left for it.
ExecutiveSettings loadExecutiveSettings(const common::ConfigNode& node);

/// The vehicle's outline for the follower: `reference_to_bumper_m` ahead of the pose, the rest of
/// `length_m` behind, `width_m` wide. Throws std::invalid_argument when the bumper distance is not within
/// (0, length_m].
Footprint vehicleFootprint(const common::VehicleSettings& vehicle, double reference_to_bumper_m);

}  // namespace ifar::executive
