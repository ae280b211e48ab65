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
#include "executive/doorway/doorway.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/modes/blocked_passage.hpp"
#include "executive/modes/collision_guard.hpp"
#include "executive/modes/cycle.hpp"
#include "executive/modes/doorway_run.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/following.hpp"
#include "executive/modes/inputs.hpp"
#include "executive/modes/mode.hpp"
#include "executive/modes/odometer.hpp"
#include "executive/modes/passage_reports.hpp"
#include "executive/modes/path_progress.hpp"
#include "executive/modes/progress_monitor.hpp"
#include "executive/modes/push_sequence.hpp"
#include "executive/modes/stall_recovery.hpp"

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
  int escalations = 0;     ///< times the progress monitor dropped what the vehicle was stuck on, this goal
  std::string reason;
};

/// The executive's problem for its heartbeat: a stale pose, force or motor input always, a stale path
/// while a goal is driven (idle or arrived, no path is expected); empty when it is fine.
std::string healthProblem(const Status& status);

struct Output {
  VelocityCommand command;  ///< after the vehicle's speed and acceleration limits; exactly zero when stopped
  WheelSpeeds wheels;       ///< the same command as wheel speeds
  Status status;
  bool mode_changed = false;
  std::optional<AffordanceEvent> affordance;  ///< set on the cycle the tactile monitor found something
  /// Set on the cycle repeated stalls gave a passage up, or an impassable gap ahead was seen.
  std::optional<BlockedPassage> blocked_passage;
  /// Set on the cycle the progress monitor escalated: what was dropped, for the log.
  std::optional<std::string> escalation;
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
  /// The task the executive pursues; Stop and EStop are overrides on top of it. Each task but the idle
  /// ones hands the cycle to one part: Follow to following (and the path progress), Doorway to the doorway
  /// run, Approach and Push to the push sequence, BackOff to the stall recovery (after a stall, or away
  /// from an object whose push was given up).
  enum class Task { Idle, Follow, Doorway, Approach, Push, ReplanWait, BackOff, Halted, Arrived };

  struct Cycle;  // per-step context

  static Mode modeOf(Task task);
  Cycle readCycle(std::int64_t now_us, const Inputs& inputs) const;
  /// The odometry reading to dead-reckon this cycle: none when absent, stale or flagged invalid.
  std::optional<OdometryReading> freshOdometry(std::int64_t now_us, const Inputs& inputs) const;
  std::int32_t staleBits(std::int64_t now_us, const Inputs& inputs) const;
  /// Takes in a new plan from the inputs (a resend of the same plan only keeps it fresh).
  void absorbPath(const Inputs& inputs);
  /// True when `incoming` (a new plan) is not adopted: the task in hand goes on along it (a push under
  /// way, a doorway run, arrived), or, waiting for a replan, it is not the replan.
  bool keepsTaskFor(const Path& incoming, const Inputs& inputs);
  void adoptPath(const Path& path);
  void startGoal(std::int64_t goal_id);
  /// Stops for the override (e-stop, stale input, non-finite pose): the reason, and an interrupted
  /// doorway run, approach or push resumes through following.
  void halt(Cycle& cycle, const Inputs& inputs, std::int32_t stale, bool e_stopped);
  void stepTask(Cycle& cycle);
  Output finishCycle(Cycle& cycle, Mode mode, std::int32_t stale, bool moving);

  void stepFollow(Cycle& cycle);
  /// Reports a blocked passage when the path ahead crosses a gap the footprint cannot get through
  /// (blocked_passage_on_sight), at most once per gap_report_repeat_s at one site.
  void reportImpassableGap(Cycle& cycle, const std::vector<geometry::Point>& ahead);
  /// Following got nowhere: counts the stall toward the path ahead, then escapes.
  void recoverFromStall(Cycle& cycle);
  void startDoorway(Cycle& cycle, const Doorway& doorway);
  void stepDoorway(Cycle& cycle);
  void stepApproach(Cycle& cycle);
  void stepPush(Cycle& cycle);
  void finishPush(Cycle& cycle);
  /// Sends `event` (AFFORDANCE) and waits for the replan.
  void waitForReplan(Cycle& cycle, const AffordanceEvent& event);
  void stepReplanWait(Cycle& cycle);
  void stepBackOff(Cycle& cycle);
  /// Following (or an approach's collision-free leg) got nowhere: back off straight or reversing along
  /// the cost-to-go, turn to the way on, then follow again.
  void beginStallEscape(Cycle& cycle);
  /// Feeds the progress monitor; when it escalates, drops what the vehicle is stuck on: the push in hand
  /// (reported as a contact not reached, so the planner tries another or backs off) or the route ahead
  /// (reported as a blocked passage, so the planner seals it and takes the next).
  void watchProgress(Cycle& cycle);
  /// A task in which the vehicle drives (waiting for a replan, stopped or idle it does not).
  bool drivingTask() const;

  ExecutiveSettings settings_;
  DifferentialDrive drive_;
  // The parts, each with one job; the mode machine passes each what it needs.
  CollisionGuard guard_;
  PathProgress progress_;
  Following following_;
  DoorwayRun doorway_run_;
  PushSequence push_;
  StallRecovery recovery_;
  PassageReports passages_;
  Odometer odometer_;
  ProgressMonitor progress_monitor_;

  Task task_ = Task::Idle;
  std::string task_reason_ = "no path yet";
  std::int64_t goal_id_ = -1;
  int pushes_ = 0;
  int replans_ = 0;
  int escalations_ = 0;
  std::int64_t replan_requested_us_ = 0;

  VelocityCommand last_command_;
  std::int64_t last_step_us_ = 0;
  bool has_stepped_ = false;
  Mode last_mode_ = Mode::Idle;
};

}  // namespace ifar::executive
