#include "executive/modes/executive.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace ifar::executive {

/// What one step() works with: the inputs as the parts see them, and what the tasks fill in.
struct Executive::Cycle {
  CycleView view;
  MotionRequest motion;
  geometry::Point target = geometry::Point::Zero();
  std::int64_t target_object_id = -1;
  std::optional<AffordanceEvent> affordance;
  std::optional<BlockedPassage> blocked_passage;
  std::optional<std::string> escalation;
};

namespace {

/// `settings` with the follower's footprint fitted to `vehicle`.
ExecutiveSettings fittedToVehicle(const ExecutiveSettings& settings, const common::VehicleSettings& vehicle)
{
  ExecutiveSettings fitted = settings;
  fitted.follower.footprint = vehicleFootprint(vehicle, settings.reference_to_bumper_m);
  return fitted;
}

}  // namespace

Executive::Executive(const ExecutiveSettings& settings, const common::VehicleSettings& vehicle)
    : settings_(fittedToVehicle(settings, vehicle)),
      drive_(vehicle),
      guard_(settings_.follower.footprint, settings_.pushed_object.guard_clearance_m,
             settings_.pushed_object.guard_horizon_s, settings_.follower.time_step_s),
      progress_(settings_),
      following_(settings_, drive_),
      doorway_run_(settings_, drive_),
      push_(settings_, vehicle, drive_),
      recovery_(settings_, drive_),
      passages_(settings_),
      progress_monitor_(settings_.progress)
{
}

Mode Executive::modeOf(Task task)
{
  switch (task) {
    case Task::Idle:
      return Mode::Idle;
    case Task::Follow:
    case Task::Doorway:
      return Mode::Follow;
    case Task::Approach:
      return Mode::Approach;
    case Task::Push:
      return Mode::Push;
    case Task::ReplanWait:
      return Mode::ReplanWait;
    case Task::BackOff:
      return Mode::Follow;  // on the way to following; the reason says it is backing off
    case Task::Halted:
      return Mode::Stop;
    case Task::Arrived:
      return Mode::Arrived;
  }
  return Mode::Stop;
}

std::string healthProblem(const Status& status)
{
  std::int32_t stale = status.stale;
  if (status.mode == Mode::Idle || status.mode == Mode::Arrived) {
    stale &= ~static_cast<std::int32_t>(kStalePath);
  }
  return stale == 0 ? std::string() : "stale inputs: " + describeStale(stale);
}

std::int32_t Executive::staleBits(std::int64_t now_us, const Inputs& inputs) const
{
  std::int32_t bits = 0;
  if (!inputs.pose || !isFresh(now_us, inputs.pose->utime, settings_.stale.pose_s)) {
    bits |= kStalePose;
  }
  if (!inputs.path || !isFresh(now_us, inputs.path->utime, settings_.stale.path_s)) {
    bits |= kStalePath;
  }
  if (!inputs.force || inputs.force->value.faulty || !std::isfinite(inputs.force->value.force_n) ||
      !isFresh(now_us, inputs.force->utime, settings_.stale.force_s)) {
    bits |= kStaleForce;
  }
  if (!inputs.motor || !inputs.motor->value.heartbeat_ok || inputs.motor->value.fault ||
      !isFresh(now_us, inputs.motor->utime, settings_.stale.motor_s)) {
    bits |= kStaleMotor;
  }
  // Without fresh points the follower and the collision guard are blind: the vehicle stops as for any
  // other lost input rather than drive on into what the lidar no longer shows.
  if (!inputs.obstacles || !isFresh(now_us, inputs.obstacles->utime, settings_.stale.obstacles_s)) {
    bits |= kStaleObstacles;
  }
  return bits;
}

std::optional<ObjectObservation> Executive::pushedObjectEstimate() const
{
  if (task_ != Task::Approach && task_ != Task::Push) {
    return std::nullopt;
  }
  const std::optional<geometry::Point> estimate = push_.objectEstimate(task_ == Task::Push);
  if (!estimate) {
    return std::nullopt;
  }
  return ObjectObservation{push_.plan().object_id, *estimate};
}

void Executive::startGoal(std::int64_t goal_id)
{
  if (goal_id != goal_id_) {
    goal_id_ = goal_id;
    pushes_ = 0;
    replans_ = 0;
    escalations_ = 0;
    progress_monitor_.startGoal();
    passages_.startGoal();
    push_.startGoal();
  }
}

void Executive::adoptPath(const Path& path)
{
  progress_.adopt(path);
  startGoal(path.goal_id);
  const Path& adopted = progress_.path();
  if (!adopted.valid) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("planner reports no path to goal {}", adopted.goal_id);
  } else if (adopted.waypoints.empty()) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("path to goal {} has no waypoints", adopted.goal_id);
  } else {
    task_ = Task::Follow;
    task_reason_.clear();
  }
}

void Executive::absorbPath(const Inputs& inputs)
{
  if (!inputs.path) {
    return;
  }
  const Path& incoming = inputs.path->value;
  const Path& current = progress_.path();
  // A resend of the path in hand only keeps it fresh; a new plan (sequence, time or goal) is absorbed.
  if (progress_.hasPath() && incoming.sequence == current.sequence && incoming.utime == current.utime &&
      incoming.goal_id == current.goal_id && incoming.valid == current.valid) {
    return;
  }
  if (keepsTaskFor(incoming, inputs)) {
    return;
  }
  const Task before = task_;
  adoptPath(incoming);
  if ((before == Task::ReplanWait || before == Task::BackOff) && task_ == Task::Follow) {
    // The bumper may still be on the object that would not move: back away from it first. Newer paths
    // are taken in while backing off, but the backing off goes on.
    task_ = Task::BackOff;
    if (before == Task::ReplanWait) {
      recovery_.beginBackingAway();
    }
  }
}

bool Executive::keepsTaskFor(const Path& incoming, const Inputs& inputs)
{
  switch (task_) {
    case Task::ReplanWait:
      // Only a path planned after the affordance update counts as the replan.
      return !(incoming.utime > replan_requested_us_ || incoming.goal_id != goal_id_);
    case Task::Approach:
    case Task::Push: {
      const bool same_goal = incoming.goal_id == goal_id_;
      const std::int64_t object_id = push_.plan().object_id;
      const bool still_pushed =
          same_goal && incoming.valid &&
          std::any_of(incoming.push_plans.begin(), incoming.push_plans.end(),
                      [object_id](const PushPlan& plan) { return plan.object_id == object_id; });
      // A push under way is finished (through its release) even when the replanned path no longer
      // needs it (the moved object may already free the passage or be tracked under a new id), or
      // when the replan finds no path at all (the object on the move, half way into a corridor, can
      // close the passage in one frame): dropping it with the object on the bumper leaves the vehicle
      // boxed in behind it. The new path is used once the push is over.
      if (still_pushed || (same_goal && task_ == Task::Push)) {
        progress_.replace(incoming);
        return true;
      }
      return false;
    }
    case Task::Doorway:
      // A run under way goes on while the new path still goes through its door, and once in the door (along
      // the lane) whatever the new path: stopping there leaves the vehicle wedged between the posts.
      if (incoming.valid && incoming.goal_id == goal_id_ && doorway_run_.keepsGoingFor(incoming)) {
        progress_.replace(incoming);
        progress_.rewind();
        return true;
      }
      return false;
    case Task::Arrived:
      // A replanned path to the same goal does not restart following for the centimetres the vehicle
      // coasted after arriving.
      if (incoming.valid && incoming.goal_id == goal_id_ && !incoming.waypoints.empty() && inputs.pose &&
          (incoming.waypoints.back().position - inputs.pose->value.position()).norm() <=
              settings_.goal_tolerance_m + settings_.arrived_hold_m) {
        progress_.replace(incoming);
        return true;
      }
      return false;
    case Task::BackOff:
    case Task::Idle:
    case Task::Follow:
    case Task::Halted:
      return false;
  }
  return false;
}

void Executive::stepFollow(Cycle& cycle)
{
  const CycleView& view = cycle.view;
  const std::vector<Waypoint>& waypoints = progress_.path().waypoints;
  if (waypoints.empty()) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("path to goal {} has no waypoints", goal_id_);
    cycle.motion.reason = task_reason_;
    return;
  }
  const std::size_t last = waypoints.size() - 1;
  progress_.advancePassed(view.pose.position(), passages_.stalledAgainNear(view.pose.position()));
  const std::size_t index = progress_.index();
  const Waypoint& waypoint = waypoints[index];
  const double distance = (waypoint.position - view.pose.position()).norm();
  cycle.target = waypoint.position;
  if (index == last && distance <= settings_.goal_tolerance_m) {
    task_ = Task::Arrived;
    task_reason_ = fmt::format("arrived at goal {} ({:.2f} m away)", goal_id_, distance);
    cycle.motion.reason = task_reason_;
    return;
  }
  if (waypoint.kind == WaypointKind::Topological && distance <= settings_.push_switch_radius_m) {
    if (const PushPlan* plan = progress_.planForWaypoint(index)) {
      push_.begin(*plan, view);
      task_ = Task::Approach;
      stepApproach(cycle);
      return;
    }
  }
  const std::vector<geometry::Point> ahead = progress_.ahead(view.pose.position());
  reportImpassableGap(cycle, ahead);
  if (const std::optional<Doorway> doorway = doorway_run_.find(ahead, waypoints.back().position, view)) {
    startDoorway(cycle, *doorway);
    return;
  }
  const Following::Step followed = following_.step(view, waypoint.position, index == last);
  cycle.motion.command = followed.result.command;
  cycle.motion.reason = fmt::format("waypoint {} of {}: {}", index, last, followed.result.reason);
  if (followed.stalled) {
    recoverFromStall(cycle);
    return;
  }
  if (followed.result.status == FollowerStatus::Arrived && index < last) {
    progress_.next();
  }
}

void Executive::reportImpassableGap(Cycle& cycle, const std::vector<geometry::Point>& ahead)
{
  const CycleView& view = cycle.view;
  if (!passages_.watchesForGaps(view.obstacles_fresh)) {
    return;
  }
  const std::optional<ImpassableGap> gap = passages_.gapToReport(ahead, view.obstacles, view.now_us);
  if (!gap) {
    return;
  }
  const geometry::Point from = view.pose.position();
  const geometry::Point to = progress_.pointAlong(from, gap->along_m + settings_.gap_report_beyond_m);
  cycle.blocked_passage = passages_.gapPassage(*gap, goal_id_, from, to);
}

void Executive::recoverFromStall(Cycle& cycle)
{
  const geometry::Point position = cycle.view.pose.position();
  const geometry::Point toward = progress_.pointAlong(position, settings_.blocked_passage_ahead_m);
  if (std::optional<BlockedPassage> passage = passages_.countStall(position, toward, goal_id_)) {
    cycle.blocked_passage = std::move(passage);
  }
  // The escape turns toward the waypoint it will follow.
  progress_.advancePassed(position, passages_.stalledAgainNear(position));
  beginStallEscape(cycle);
}

void Executive::startDoorway(Cycle& cycle, const Doorway& doorway)
{
  doorway_run_.start(doorway, cycle.view);
  task_ = Task::Doorway;
  stepDoorway(cycle);
}

void Executive::stepDoorway(Cycle& cycle)
{
  const DoorwayRun::Step step = doorway_run_.step(cycle.view, guard_, cycle.motion);
  if (step.progress == DoorwayRun::Progress::GivenUp) {
    task_ = Task::Follow;
    following_.restart();
    stepFollow(cycle);
    cycle.motion.reason = fmt::format("{}; {}", step.given_up, cycle.motion.reason);
    return;
  }
  cycle.target = doorway_run_.runEnd();
  if (step.progress == DoorwayRun::Progress::Driving) {
    return;
  }
  // Through: the waypoints at the posts and on the run are behind.
  progress_.advanceWhile(
      [this](const geometry::Point& waypoint) { return doorway_run_.leftBehind(waypoint); });
  doorway_run_.finish();
  task_ = Task::Follow;
  following_.restart();
  stepFollow(cycle);
}

void Executive::stepApproach(Cycle& cycle)
{
  cycle.target_object_id = push_.plan().object_id;
  const PushSequence::Step step = push_.approach(cycle.view, guard_, cycle.motion);
  cycle.target = step.target;
  switch (step.next) {
    case PushSequence::Next::Drive:
      return;
    case PushSequence::Next::Escape:
      beginStallEscape(cycle);
      return;
    case PushSequence::Next::WaitForReplan:
      waitForReplan(cycle, *step.affordance);
      return;
    case PushSequence::Next::Push:
    case PushSequence::Next::Finished:
      task_ = Task::Push;
      stepPush(cycle);
      return;
  }
}

void Executive::stepPush(Cycle& cycle)
{
  cycle.target_object_id = push_.plan().object_id;
  const PushSequence::Step step = push_.push(cycle.view, guard_, cycle.motion);
  cycle.target = step.target;
  if (step.object_left_at) {
    passages_.rememberPushedObject(*step.object_left_at);
  }
  if (step.affordance) {
    cycle.affordance = step.affordance;
  }
  switch (step.next) {
    case PushSequence::Next::WaitForReplan:
      waitForReplan(cycle, *step.affordance);
      return;
    case PushSequence::Next::Finished:
      finishPush(cycle);
      return;
    case PushSequence::Next::Drive:
    case PushSequence::Next::Escape:
    case PushSequence::Next::Push:
      return;
  }
}

void Executive::finishPush(Cycle& cycle)
{
  ++pushes_;
  const std::int64_t object_id = push_.plan().object_id;
  cycle.motion.command = {};
  if (!progress_.path().valid || progress_.path().waypoints.empty()) {
    // The replan during the push found no path: stop until the planner has one.
    const Path current = progress_.path();
    adoptPath(current);
    cycle.motion.reason = fmt::format("push of object {} finished; {}", object_id, task_reason_);
    return;
  }
  const int push_waypoint = progress_.pushWaypointIndex(object_id);
  if (push_waypoint >= 0) {
    progress_.setIndex(static_cast<std::size_t>(push_waypoint));
  } else {
    progress_.rewind();
  }
  task_ = Task::Follow;
  cycle.motion.reason = fmt::format("push of object {} finished", object_id);
}

void Executive::waitForReplan(Cycle& cycle, const AffordanceEvent& event)
{
  cycle.affordance = event;
  task_ = Task::ReplanWait;
  replan_requested_us_ = cycle.view.now_us;
  ++replans_;
  task_reason_ = fmt::format("waiting for replan: {}", event.text);
  cycle.motion.reason = task_reason_;
  cycle.motion.command = {};
}

void Executive::stepReplanWait(Cycle& cycle)
{
  const std::int64_t object_id = push_.plan().object_id;
  cycle.target_object_id = object_id;
  const double waited_s = static_cast<double>(cycle.view.now_us - replan_requested_us_) * 1e-6;
  if (waited_s > settings_.replan_timeout_s) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("no replanned path within {:.1f} s after the affordance update of object {}",
                               settings_.replan_timeout_s, object_id);
  }
  cycle.motion.reason = task_reason_;
}

void Executive::beginStallEscape(Cycle& cycle)
{
  recovery_.beginStallEscape();
  task_ = Task::BackOff;
  following_.restart();
  stepBackOff(cycle);
}

void Executive::stepBackOff(Cycle& cycle)
{
  const std::int64_t object_id = push_.plan().object_id;
  const bool after_stall = recovery_.afterStall();
  if (!after_stall) {
    cycle.target_object_id = object_id;
  }
  const common::Span<const geometry::Point> away_obstacles =
      after_stall ? cycle.view.obstacles : push_.objectFreeObstacles(cycle.view);
  switch (recovery_.step(cycle.view, progress_.wayOn(), away_obstacles, object_id, guard_, cycle.motion)) {
    case StallRecovery::Next::Continue:
      return;
    case StallRecovery::Next::FollowNow:
      task_ = Task::Follow;
      following_.restart();
      stepFollow(cycle);
      return;
    case StallRecovery::Next::FollowNextCycle:
      task_ = Task::Follow;
      following_.restart();
      return;
  }
}

Executive::Cycle Executive::readCycle(std::int64_t now_us, const Inputs& inputs) const
{
  Cycle cycle;
  CycleView& view = cycle.view;
  view.now_us = now_us;
  if (inputs.pose) {
    view.pose = inputs.pose->value;
  }
  if (inputs.force && !inputs.force->value.faulty) {
    view.force_n = inputs.force->value.force_n;
  }
  if (inputs.obstacles && isFresh(now_us, inputs.obstacles->utime, settings_.stale.obstacles_s)) {
    view.obstacles =
        common::Span<const geometry::Point>(inputs.obstacles->value.data(), inputs.obstacles->value.size());
    view.obstacles_fresh = true;
  }
  if (inputs.pushed_object && isFresh(now_us, inputs.pushed_object->utime, settings_.stale.obstacles_s)) {
    view.pushed_object = inputs.pushed_object->value;
  }
  view.wheels = odometer_.track();
  return cycle;
}

std::optional<OdometryReading> Executive::freshOdometry(std::int64_t now_us, const Inputs& inputs) const
{
  if (!inputs.odometry || !inputs.odometry->value.valid ||
      !isFresh(now_us, inputs.odometry->utime, settings_.stale.odometry_s) ||
      !std::isfinite(inputs.odometry->value.linear) || !std::isfinite(inputs.odometry->value.angular)) {
    return std::nullopt;
  }
  return inputs.odometry->value;
}

void Executive::halt(Cycle& cycle, const Inputs& inputs, std::int32_t stale, bool e_stopped)
{
  std::string& reason = cycle.motion.reason;
  if (e_stopped) {
    reason =
        fmt::format("e-stop engaged by {}: {}", inputs.e_stop->value.source, inputs.e_stop->value.reason);
  } else if (stale != 0) {
    reason = fmt::format("stale input: {}", describeStale(stale));
    if ((stale & kStaleMotor) != 0 && inputs.motor && !inputs.motor->value.reason.empty()) {
      reason += fmt::format(" (motor: {})", inputs.motor->value.reason);
    }
  } else {
    reason = "pose is not finite";
  }
  if (task_ == Task::Approach || task_ == Task::Push || task_ == Task::Doorway) {
    // The vehicle may have drifted off the plan while stopped: resume by following the (newest) path,
    // which brings it back to the push through the topological waypoint.
    task_ = Task::Follow;
    progress_.rewind();
  }
}

void Executive::stepTask(Cycle& cycle)
{
  switch (task_) {
    case Task::Follow:
      stepFollow(cycle);
      break;
    case Task::Doorway:
      stepDoorway(cycle);
      break;
    case Task::Approach:
      stepApproach(cycle);
      break;
    case Task::Push:
      stepPush(cycle);
      break;
    case Task::ReplanWait:
      stepReplanWait(cycle);
      break;
    case Task::BackOff:
      stepBackOff(cycle);
      break;
    case Task::Idle:
    case Task::Halted:
    case Task::Arrived:
      cycle.motion.reason = task_reason_;
      break;
  }
}

Output Executive::step(std::int64_t now_us, const Inputs& inputs)
{
  odometer_.update(now_us, freshOdometry(now_us, inputs));
  Cycle cycle = readCycle(now_us, inputs);
  const std::int32_t stale = staleBits(now_us, inputs);
  absorbPath(inputs);

  const bool active = drivingTask() || task_ == Task::ReplanWait;
  const bool e_stopped = inputs.e_stop && inputs.e_stop->value.engaged;
  const geometry::Pose2& pose = cycle.view.pose;
  const bool pose_finite = std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.heading);
  const bool halted = e_stopped || (active && (stale != 0 || !pose_finite));
  bool moving = false;
  if (halted) {
    halt(cycle, inputs, stale, e_stopped);
  } else {
    stepTask(cycle);
    watchProgress(cycle);
    moving = drivingTask();
  }
  const Mode mode = halted ? (e_stopped ? Mode::EStop : Mode::Stop) : modeOf(task_);
  return finishCycle(cycle, mode, stale, moving);
}

bool Executive::drivingTask() const
{
  return task_ == Task::Follow || task_ == Task::Doorway || task_ == Task::Approach || task_ == Task::Push ||
         task_ == Task::BackOff;
}

void Executive::watchProgress(Cycle& cycle)
{
  if (!progress_.hasPath() || !progress_.path().valid || progress_.path().waypoints.empty()) {
    return;
  }
  const geometry::Point position = cycle.view.pose.position();
  const double stuck_s = settings_.progress.timeout_s;
  if (!progress_monitor_.update(cycle.view.now_us, position, progress_.remainingLength(position),
                                drivingTask())) {
    return;
  }
  ++escalations_;
  const std::string why = fmt::format("no progress toward the goal for {:.0f} s", stuck_s);
  if (task_ == Task::Approach || task_ == Task::Push) {
    AffordanceEvent event = push_.givenUpForProgress(why);
    cycle.escalation =
        fmt::format("escalation {}: {}: push of object {} dropped", escalations_, why, event.object_id);
    waitForReplan(cycle, event);
    return;
  }
  const geometry::Point toward = progress_.pointAlong(position, settings_.blocked_passage_ahead_m);
  BlockedPassage passage;
  passage.goal_id = goal_id_;
  passage.from = position;
  passage.to = toward;
  passage.text = fmt::format("{}: route toward ({:.2f}, {:.2f}) dropped", why, toward.x(), toward.y());
  cycle.escalation = fmt::format("escalation {}: {}", escalations_, passage.text);
  if (!cycle.blocked_passage) {
    cycle.blocked_passage = std::move(passage);
  }
}

Output Executive::finishCycle(Cycle& cycle, Mode mode, std::int32_t stale, bool moving)
{
  const std::int64_t now_us = cycle.view.now_us;
  Output output;
  if (moving) {
    const double elapsed_s = has_stepped_ ? std::clamp(static_cast<double>(now_us - last_step_us_) * 1e-6,
                                                       0.0, settings_.max_cycle_gap_s)
                                          : 0.0;
    output.command = drive_.limit(cycle.motion.command, last_command_, elapsed_s);
  }
  output.wheels = drive_.toWheelSpeeds(output.command);
  last_command_ = output.command;
  last_step_us_ = now_us;
  has_stepped_ = true;

  Status& status = output.status;
  status.mode = mode;
  status.goal_id = goal_id_;
  status.waypoint_index = progress_.hasPath() ? static_cast<int>(progress_.index()) : -1;
  status.target = cycle.target;
  status.target_object_id = cycle.target_object_id;
  status.stale = stale;
  status.pushes = pushes_;
  status.replans = replans_;
  status.escalations = escalations_;
  status.reason = std::move(cycle.motion.reason);
  output.affordance = std::move(cycle.affordance);
  output.blocked_passage = std::move(cycle.blocked_passage);
  output.escalation = std::move(cycle.escalation);
  output.mode_changed = mode != last_mode_;
  last_mode_ = mode;
  return output;
}

}  // namespace ifar::executive
