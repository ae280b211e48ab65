#pragma once
// The executive's mode machine (paper section VII.B, Algorithm 2): follows the global path with the
// collision-free local planner, switches to the push plan near a topological waypoint, adapts from
// touch, and stops whenever an input it depends on goes stale or an e-stop is engaged.
//
// One call per control cycle, step(now, inputs) -> Output: the daemon and the headless runner drive the
// same code. No LCM, no clocks: time comes in as `now`.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/vehicle.hpp"
#include "executive/affordance/affordance_event.hpp"
#include "executive/affordance/tactile_monitor.hpp"
#include "executive/doorway/doorway.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/inputs.hpp"
#include "executive/modes/mode.hpp"
#include "executive/pusher/approach.hpp"
#include "executive/pusher/push_tracker.hpp"

namespace ifar::executive {

/// What EXEC_STATUS reports.
struct Status {
  Mode mode = Mode::Idle;
  std::int64_t goal_id = -1;
  int waypoint_index = -1;
  geometry::Point target = geometry::Point::Zero();
  std::int64_t target_object_id = -1;
  std::int32_t stale = 0;  ///< StaleInput bits
  int pushes = 0;          ///< push plans completed for this goal
  int replans = 0;         ///< replans requested for this goal
  std::string reason;
};

/// The executive's problem for its heartbeat: a stale pose, force or motor input always, a stale path
/// while a goal is driven (idle or arrived, no path is expected); empty when it is fine.
std::string healthProblem(const Status& status);

/// A passage the vehicle could not get through: following toward `to` stalled `stalls` times within
/// kStallSiteRadiusM of `from`. The daemon publishes it as BLOCKED_PASSAGE; the planner seals the
/// narrowest point between the two and routes around it.
struct BlockedPassage {
  std::int64_t goal_id = -1;
  geometry::Point from = geometry::Point::Zero();  ///< the vehicle, world frame
  geometry::Point to = geometry::Point::Zero();    ///< the path point it could not reach
  int stalls = 0;                                  ///< 0: an impassable gap seen ahead, no stall
  std::string text;                                ///< for people
};

struct Output {
  VelocityCommand command;  ///< after the vehicle's speed and acceleration limits; exactly zero when stopped
  WheelSpeeds wheels;       ///< the same command as wheel speeds
  Status status;
  bool mode_changed = false;
  std::optional<AffordanceEvent> affordance;  ///< set on the cycle the tactile monitor found something
  /// Set on the cycle repeated stalls gave a passage up, or an impassable gap ahead was seen.
  std::optional<BlockedPassage> blocked_passage;
};

class Executive {
 public:
  /// Fits the follower's footprint to `vehicle` (see vehicleFootprint; throws std::invalid_argument).
  Executive(const ExecutiveSettings& settings, const common::VehicleSettings& vehicle);

  /// One control cycle at `now_us` (microseconds, the clock of the inputs' stamps).
  Output step(std::int64_t now_us, const Inputs& inputs);

  Mode mode() const { return last_mode_; }
  /// While approaching or pushing: the object's id and where the plan expects its centroid now (world
  /// frame), for finding its returns (the daemon's pushed_object input). Empty in the other modes.
  std::optional<ObjectObservation> pushedObjectEstimate() const;
  const ExecutiveSettings& settings() const { return settings_; }

 private:
  /// The task the executive pursues; Stop and EStop are overrides on top of it.
  /// BackOff: reversing away from an object whose push was given up, before following a new path
  /// (the follower only plans forward, so with the object on the bumper it would be boxed in), or after
  /// following got nowhere for stall_timeout_s (wedged in a door, dithering beside a wall).
  /// Doorway: following drives a door barely wider than the vehicle as a straight run (executive/doorway).
  enum class Task { Idle, Follow, Doorway, Approach, Push, ReplanWait, BackOff, Halted, Arrived };

  struct Cycle;  // per-step context

  std::int32_t staleBits(std::int64_t now_us, const Inputs& inputs) const;
  /// Takes in a new plan from the inputs (a resend of the same plan only keeps it fresh).
  void absorbPath(const Inputs& inputs);
  void adoptPath(const Path& path);
  void stepFollow(Cycle& cycle);
  /// Moves waypoint_index_ past the intermediate waypoints the vehicle has passed (never past a
  /// topological waypoint with a push plan).
  void advancePassedWaypoints(const Cycle& cycle);
  /// The vehicle's position, then the waypoints ahead up to where a push takes over (pushing goes through
  /// its own gap).
  std::vector<geometry::Point> pathAhead(const Cycle& cycle) const;
  /// The first doorway on the path ahead that is worth a straight run and not given up lately.
  std::optional<Doorway> doorwayAhead(const Cycle& cycle) const;
  /// Reports a blocked passage when the path ahead crosses a gap the footprint cannot get through
  /// (blocked_passage_on_sight), at most once per gap_report_repeat_s at one site.
  void reportImpassableGap(Cycle& cycle);
  /// True when a post of `gap` is within pushed_object.radius_m of where a push left an object.
  bool besidePushedObject(const ImpassableGap& gap) const;
  /// Where the push just finished or abandoned left its object: `observed` when given, else the expected
  /// centroid at the current primitive (call while still pushing).
  void rememberPushedObject(const std::optional<geometry::Point>& observed);
  void startDoorway(Cycle& cycle, const Doorway& doorway);
  void stepDoorway(Cycle& cycle);
  /// True when the path from the current waypoint on still goes through the doorway being driven.
  bool pathCrossesDoorway(const Path& path) const;
  void stepApproach(Cycle& cycle);
  /// Aligning at the stand-off point turns on the spot; when a point ahead would stop that turn, backs
  /// straight up (at most kAlignBackUpM per approach) until the turn is free. True while it does.
  bool backUpToAlign(Cycle& cycle, common::Span<const geometry::Point> obstacles);
  void stepPush(Cycle& cycle);
  /// Sends AFFORDANCE "not reached" for the active plan's object and waits for the replan.
  void giveUpUnreachableContact(Cycle& cycle, const std::string& contact);
  /// Sends AFFORDANCE (not pushable, cost higher, `text`) for the active plan's object and waits for the
  /// replan: the vehicle stood still where the plan needs it to move.
  void giveUpPlan(Cycle& cycle, const std::string& text);
  void stepReplanWait(Cycle& cycle);
  void stepBackOff(Cycle& cycle);
  /// Following (or an approach's collision-free leg) got nowhere: back off straight or reversing along
  /// the cost-to-go, turn to the way on, then follow again.
  void beginStallEscape(Cycle& cycle);
  void startGoal(std::int64_t goal_id);
  const PushPlan* planForWaypoint(std::size_t index) const;
  int pushWaypointIndex(std::int64_t object_id) const;
  static Mode modeOf(Task task);
  /// The expected centroid path of the active plan's object: at first contact, then after each primitive.
  void startObjectPath();
  /// The fresh obstacle points without the returns on the object being approached or pushed.
  common::Span<const geometry::Point> objectFreeObstacles(const Cycle& cycle);
  /// Stops `cycle.desired` when it drives the footprint toward a point closer than the guard clearance.
  void guardCommand(Cycle& cycle, common::Span<const geometry::Point> obstacles) const;
  /// Sets `cycle.desired` to driving straight at `linear` m/s, or, when the guard stops that, along the
  /// first free arc of the same speed (gentle before tight, turning first toward the way on); zero when
  /// every one is guarded. Wedged at a slant, straight back closes in on a wall that an arc clears.
  void guardedEscape(Cycle& cycle, double linear, common::Span<const geometry::Point> obstacles) const;
  /// How far (up to `limit_m`) the vehicle can drive straight from `pose` (sign -1 back, +1 ahead)
  /// without its footprint coming within the guard clearance of a point it is not already that close to.
  double freeStraightDistance(const geometry::Pose2& pose, double sign,
                              common::Span<const geometry::Point> obstacles, double limit_m) const;
  /// True when turning on the spot from `pose` to `heading` keeps the footprint out of the guard clearance
  /// (plus `margin_m`) of every point it is not already that close to.
  bool freeTurn(const geometry::Pose2& pose, double heading, common::Span<const geometry::Point> obstacles,
                double margin_m = 0.0) const;
  /// Reversing along the follower's cost-to-go toward the current waypoint, when it lies behind the
  /// vehicle and a reversing arc gets closer to it; none otherwise.
  std::optional<FollowerResult> reverseTowardWaypoint(const Cycle& cycle) const;
  /// After a stall's straight escape: the heading the follower's cost-to-go wants, when turning to it on
  /// the spot first is needed and free (a door entered at a slant wedges the corners on its posts).
  std::optional<double> stallTurnHeading(const Cycle& cycle) const;
  /// Restarts the watch for standing still (entering a doorway run or a push approach).
  void anchorMotion(const Cycle& cycle);
  /// True when the vehicle has neither moved 0.1 m nor turned 0.3 rad for twice stall_timeout_s since the
  /// last anchorMotion or motion.
  bool standingStill(const Cycle& cycle);
  /// Counts a stall toward `target`; the blocked_passage_stalls-th at one site reports a blocked passage.
  void countStall(Cycle& cycle, const geometry::Point& target);

  ExecutiveSettings settings_;
  common::VehicleSettings vehicle_;
  DifferentialDrive drive_;
  double max_push_force_n_;

  Task task_ = Task::Idle;
  std::string task_reason_ = "no path yet";
  bool has_path_ = false;
  Path path_;
  std::size_t waypoint_index_ = 0;
  std::int64_t goal_id_ = -1;
  int pushes_ = 0;
  int replans_ = 0;

  PushPlan active_plan_;
  std::vector<geometry::Point> object_path_;   // see startObjectPath()
  std::size_t push_control_index_ = 0;         // the tracker's current primitive
  PushPhase push_phase_ = PushPhase::Pushing;  // its phase last cycle: motion is re-anchored on a change
  std::vector<geometry::Point> object_free_obstacles_;  // reused buffer of objectFreeObstacles()
  Approach approach_;
  PushTracker tracker_;
  TactileMonitor tactile_;
  std::int64_t replan_requested_us_ = 0;
  std::optional<geometry::Point> backoff_start_;  // where BackOff began reversing (set on its first step)
  bool backoff_after_stall_ = false;              // BackOff because following got nowhere, not after a push
  std::optional<std::int64_t> approach_escaped_object_;  // the object whose approach used its one escape
  std::optional<geometry::Point> align_backup_start_;    // where this approach began backing up to align
  // Objects that jammed after sliding, this goal: a second jam of one is reported unpushable.
  std::vector<std::int64_t> jammed_objects_;
  double stall_escape_sign_ = 0.0;  // after a stall: -1 reversing, +1 driving ahead, 0 not chosen yet
  bool stall_reversing_ = false;    // the escape reverses along the cost-to-go to a waypoint behind
  std::optional<double> stall_turn_heading_;  // after the straight escape: turning on the spot to this
  std::optional<Doorway> doorway_;            // being driven through (Task::Doorway)
  Approach doorway_run_;                      // to the run's start, square to the door, along the run
  std::int64_t doorway_started_us_ = 0;
  geometry::Pose2 motion_anchor_;      // where a doorway run or a push approach last moved from ...
  std::int64_t motion_anchor_us_ = 0;  // ... and when
  /// Doorways whose run timed out, by centre, and until when (microseconds) they are left to the follower.
  std::vector<std::pair<geometry::Point, std::int64_t>> doorways_given_up_;
  std::int64_t stall_turn_since_us_ = 0;                  // since then
  geometry::Pose2 stall_anchor_;                          // where following last moved from
  std::int64_t stall_anchor_us_ = -1;                     // and when (-1: not following)
  std::int64_t last_follow_us_ = 0;                       // the last cycle that followed
  geometry::Point stall_site_ = geometry::Point::Zero();  // where the current series of stalls began
  int stalls_at_site_ = 0;                                // stalls of that series, toward one waypoint
  std::optional<geometry::Point> last_stall_at_;          // where following last stalled (this goal)
  std::optional<geometry::Point> repeated_stall_at_;      // ... the last within 1 m of the stall before
  geometry::Point stall_site_target_ = geometry::Point::Zero();
  geometry::Point gap_reported_at_ = geometry::Point::Zero();  // the last impassable gap reported ...
  std::int64_t gap_reported_us_ = -1;                          // ... and when (-1: none yet)
  std::vector<geometry::Point> pushed_objects_left_at_;        // where the last few pushes left their objects

  VelocityCommand last_command_;
  std::int64_t last_step_us_ = 0;
  bool has_stepped_ = false;
  Mode last_mode_ = Mode::Idle;
};

}  // namespace ifar::executive
