#include "executive/modes/executive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/geometry/segment.hpp"
#include "executive/follower/arc.hpp"
#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

/// What one step() works with; the sub-steps fill in the command and the report.
struct Executive::Cycle {
  std::int64_t now_us = 0;
  const Inputs& inputs;
  geometry::Pose2 pose;
  double force_n = 0.0;
  common::Span<const geometry::Point> obstacles;
  bool obstacles_fresh = false;
  VelocityCommand desired;
  std::string reason;
  geometry::Point target = geometry::Point::Zero();
  std::int64_t target_object_id = -1;
  std::optional<AffordanceEvent> affordance;
  std::optional<BlockedPassage> blocked_passage;
};

namespace {

/// Metres beyond the goal tolerance within which an arrived vehicle stays arrived for a new plan.
constexpr double kStayArrivedM = 0.1;
// After a stall's straight escape the vehicle turns on the spot to the cost-to-go's heading when it is off
// by more than this, for at most this long; the straight escape goes on for up to this many release
// distances while that turn is not free.
constexpr double kStallTurnToleranceRad = 0.2;
constexpr double kStallTurnTimeoutS = 5.0;
constexpr double kStallEscapeReleases = 3.0;
/// Backing up at most this far to free the turn at the stand-off point: a wall square ahead needs 0.2 m
/// at most (the front corners sweep the footprint's 0.57 m circumradius, the bumper is 0.45 m ahead), a
/// slanted one or a corner more.
constexpr double kAlignBackUpM = 0.5;
/// ... until the turn keeps this much more than the guard clearance: the guard steps the turn otherwise
/// than freeTurn and would stop one that only just clears.
constexpr double kAlignTurnMarginM = 0.03;
/// A stall escape toward a waypoint behind the vehicle reverses along the follower's cost-to-go (not
/// straight back) while the turn to face the way on is not free, for up to this far: out of a dead-end
/// aisle too narrow to turn in, back to where it widens.
constexpr double kReversingEscapeM = 2.0;
/// Metres of cost-to-go an escape arc must gain to count as reversing toward the waypoint.
constexpr double kReversingProgressM = 0.01;
/// Stalls within this distance of the first one of a series, toward waypoints this close to each other,
/// count as the same passage.
constexpr double kStallSiteRadiusM = 1.0;
/// The guard's comparisons allow this much rounding: distances computed at a slant to the axes are off by
/// it, and a vehicle backing straight along a wall exactly guard_clearance_m away was stopped for good.
constexpr double kGuardRoundingM = 1e-4;
constexpr std::size_t kPushedObjectsRemembered = 8;
/// A blocked passage is reported toward the path point this far ahead (along the path), not the
/// waypoint: the planner seals beyond the vehicle's inflation, so a waypoint a step ahead leaves it no
/// room, and one at the end of a long leg lets the seal land anywhere along it.
constexpr double kBlockedPassageLookAheadM = 2.5;

/// The point `distance` along the polyline from `position` through `waypoints[next]`, `waypoints[next +
/// 1]`, ...; the last waypoint when the path is shorter.
geometry::Point pointAlongPath(const geometry::Point& position, const std::vector<Waypoint>& waypoints,
                               std::size_t next, double distance)
{
  geometry::Point from = position;
  for (std::size_t index = next; index < waypoints.size(); ++index) {
    const geometry::Point to = waypoints[index].position;
    const double leg = (to - from).norm();
    if (leg >= distance && leg > 0.0) {
      return from + (to - from) * (distance / leg);
    }
    distance -= leg;
    from = to;
  }
  return from;
}

/// The approach that drives a doorway's run: to its start, square to the door, along it to its end. No
/// bumper contact ends it.
ApproachSettings doorwayRunSettings(const ExecutiveSettings& settings, const DifferentialDrive& drive)
{
  ApproachSettings run = settings.approach;
  // Nothing is pushed: the turn square to the door may use the vehicle's own turn rate.
  run.control.max_angular_velocity = drive.maxAngularVelocity();
  run.standoff_m = settings.doorway.approach_m + settings.doorway.exit_m;
  run.creep_speed = settings.doorway.speed;
  run.contact_tolerance_m = settings.waypoint_tolerance_m / 4.0;
  run.contact_force_n = std::numeric_limits<double>::infinity();
  // Arriving at the run's start at speed and within this of its heading, the lane tracker turns the rest
  // while moving (a stop and a turn on the spot cost 2-4 s a door).
  run.stop_at_standoff = false;
  run.heading_tolerance_rad = 0.3;
  run.standoff_tolerance_m = std::max(run.standoff_tolerance_m, 0.15);
  return run;
}

bool fresh(std::int64_t now_us, std::int64_t stamp_us, double threshold_s)
{
  return static_cast<double>(now_us - stamp_us) <= threshold_s * 1e6;
}

}  // namespace

Executive::Executive(const ExecutiveSettings& settings, const common::VehicleSettings& vehicle)
    : settings_(settings),
      vehicle_(vehicle),
      drive_(vehicle),
      max_push_force_n_(std::min(vehicle.maxPushForce(), vehicle.force_sensor_range_n))
{
  settings_.follower.footprint = vehicleFootprint(vehicle, settings.reference_to_bumper_m);
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
  if (!inputs.pose || !fresh(now_us, inputs.pose->utime, settings_.stale.pose_s)) {
    bits |= kStalePose;
  }
  if (!inputs.path || !fresh(now_us, inputs.path->utime, settings_.stale.path_s)) {
    bits |= kStalePath;
  }
  if (!inputs.force || inputs.force->value.faulty || !std::isfinite(inputs.force->value.force_n) ||
      !fresh(now_us, inputs.force->utime, settings_.stale.force_s)) {
    bits |= kStaleForce;
  }
  if (!inputs.motor || !inputs.motor->value.heartbeat_ok || inputs.motor->value.fault ||
      !fresh(now_us, inputs.motor->utime, settings_.stale.motor_s)) {
    bits |= kStaleMotor;
  }
  return bits;
}

void Executive::startGoal(std::int64_t goal_id)
{
  if (goal_id != goal_id_) {
    goal_id_ = goal_id;
    pushes_ = 0;
    replans_ = 0;
    stalls_at_site_ = 0;
    last_stall_at_.reset();
    repeated_stall_at_.reset();
    jammed_objects_.clear();
  }
}

void Executive::adoptPath(const Path& path)
{
  path_ = path;
  has_path_ = true;
  startGoal(path.goal_id);
  waypoint_index_ = std::min<std::size_t>(1, path_.waypoints.empty() ? 0 : path_.waypoints.size() - 1);
  if (!path_.valid) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("planner reports no path to goal {}", path_.goal_id);
  } else if (path_.waypoints.empty()) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("path to goal {} has no waypoints", path_.goal_id);
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
  // A resend of the path in hand only keeps it fresh; a new plan (sequence, time or goal) is absorbed.
  if (has_path_ && incoming.sequence == path_.sequence && incoming.utime == path_.utime &&
      incoming.goal_id == path_.goal_id && incoming.valid == path_.valid) {
    return;
  }
  switch (task_) {
    case Task::ReplanWait:
      // Only a path planned after the affordance update counts as the replan.
      if (incoming.utime > replan_requested_us_ || incoming.goal_id != goal_id_) {
        adoptPath(incoming);
        if (task_ == Task::Follow) {
          // The bumper is still on the object that would not move: back away from it first.
          task_ = Task::BackOff;
          backoff_start_.reset();
        }
      }
      return;
    case Task::BackOff:
      // Newer paths are taken in, but the backing off goes on.
      adoptPath(incoming);
      if (task_ == Task::Follow) {
        task_ = Task::BackOff;
      }
      return;
    case Task::Approach:
    case Task::Push: {
      const bool same_goal = incoming.goal_id == goal_id_;
      const bool still_pushed =
          same_goal && incoming.valid &&
          std::any_of(incoming.push_plans.begin(), incoming.push_plans.end(),
                      [this](const PushPlan& plan) { return plan.object_id == active_plan_.object_id; });
      // A push under way is finished (through its release) even when the replanned path no longer
      // needs it (the moved object may already free the passage or be tracked under a new id), or
      // when the replan finds no path at all (the object on the move, half way into a corridor, can
      // close the passage in one frame): dropping it with the object on the bumper leaves the vehicle
      // boxed in behind it (bench Willow t7 with the walls known: the new approach's stand-off point
      // was behind the vehicle in a 1.1 m corridor, and the object was given up as unpushable).
      if (still_pushed || (same_goal && task_ == Task::Push)) {
        // Keep executing the plan in hand; the new path is used once the push is over.
        path_ = incoming;
        return;
      }
      adoptPath(incoming);
      return;
    }
    case Task::Doorway:
      // A run under way goes on while the new path still goes through its door, and once in the door (along
      // the lane) whatever the new path: stopping there leaves the vehicle wedged between the posts.
      if (incoming.valid && incoming.goal_id == goal_id_ &&
          (doorway_run_.phase() == ApproachPhase::Creep || pathCrossesDoorway(incoming))) {
        path_ = incoming;
        waypoint_index_ = std::min<std::size_t>(1, path_.waypoints.size() - 1);
        return;
      }
      adoptPath(incoming);
      return;
    case Task::Arrived:
      // A replanned path to the same goal does not restart following for the centimetres the vehicle
      // coasted after arriving (it stopped 0.31 m from the goal and followed again, in the demo).
      if (incoming.valid && incoming.goal_id == goal_id_ && !incoming.waypoints.empty() && inputs.pose &&
          (incoming.waypoints.back().position - inputs.pose->value.position()).norm() <=
              settings_.goal_tolerance_m + kStayArrivedM) {
        path_ = incoming;
        return;
      }
      adoptPath(incoming);
      return;
    case Task::Idle:
    case Task::Follow:
    case Task::Halted:
      adoptPath(incoming);
      return;
  }
}

const PushPlan* Executive::planForWaypoint(std::size_t index) const
{
  const auto plan_at = [this](int plan_index) -> const PushPlan* {
    if (plan_index < 0 || static_cast<std::size_t>(plan_index) >= path_.push_plans.size()) {
      return nullptr;
    }
    return &path_.push_plans[static_cast<std::size_t>(plan_index)];
  };
  if (const PushPlan* plan = plan_at(path_.waypoints[index].push_plan_index)) {
    return plan;
  }
  if (index + 1 < path_.waypoints.size() && path_.waypoints[index + 1].kind == WaypointKind::Push) {
    return plan_at(path_.waypoints[index + 1].push_plan_index);
  }
  return nullptr;
}

int Executive::pushWaypointIndex(std::int64_t object_id) const
{
  for (std::size_t index = 0; index < path_.waypoints.size(); ++index) {
    const Waypoint& waypoint = path_.waypoints[index];
    if (waypoint.kind == WaypointKind::Push && waypoint.object_id == object_id) {
      return static_cast<int>(index);
    }
  }
  return -1;
}

void Executive::stepFollow(Cycle& cycle)
{
  const std::vector<Waypoint>& waypoints = path_.waypoints;
  if (waypoints.empty()) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("path to goal {} has no waypoints", goal_id_);
    cycle.reason = task_reason_;
    return;
  }
  const std::size_t last = waypoints.size() - 1;
  advancePassedWaypoints(cycle);
  const auto distance_to = [&cycle, &waypoints](std::size_t index) {
    return (waypoints[index].position - cycle.pose.position()).norm();
  };
  cycle.target = waypoints[waypoint_index_].position;
  if (waypoint_index_ == last && distance_to(last) <= settings_.goal_tolerance_m) {
    task_ = Task::Arrived;
    task_reason_ = fmt::format("arrived at goal {} ({:.2f} m away)", goal_id_, distance_to(last));
    cycle.reason = task_reason_;
    return;
  }

  const Waypoint& waypoint = waypoints[waypoint_index_];
  if (waypoint.kind == WaypointKind::Topological &&
      distance_to(waypoint_index_) <= settings_.push_switch_radius_m) {
    if (const PushPlan* plan = planForWaypoint(waypoint_index_)) {
      active_plan_ = *plan;
      startObjectPath();
      approach_.begin(active_plan_.contact_pose, cycle.pose, settings_.approach);
      align_backup_start_.reset();
      anchorMotion(cycle);
      task_ = Task::Approach;
      stepApproach(cycle);
      return;
    }
  }

  reportImpassableGap(cycle);
  if (const std::optional<Doorway> doorway = doorwayAhead(cycle)) {
    startDoorway(cycle, *doorway);
    return;
  }

  // The follower stops at its target: at the goal that must be within the arrival tolerance, or the
  // vehicle would halt between the two tolerances and never arrive.
  FollowerSettings follower = settings_.follower;
  follower.goal_tolerance_m =
      waypoint_index_ == last ? settings_.goal_tolerance_m : settings_.waypoint_tolerance_m;
  // Hemmed in at about the clearance (along a wall every arc dips a little below it; turning swings a
  // corner closer), or lined up with a door barely wider than the vehicle plus twice the clearance (only
  // turning on the spot is left): the follower retries with the clearance lowered to the guard's.
  const FollowerResult result =
      followSqueezing(cycle.pose, waypoint.position, waypoint_index_ == last, cycle.obstacles, follower,
                      settings_.pushed_object.guard_clearance_m, drive_);
  cycle.desired = result.command;
  cycle.reason = fmt::format("waypoint {} of {}: {}", waypoint_index_, last, result.reason);
  // Following that gets nowhere (the arcs dither left and right, wedged at a door or beside a wall with
  // the target behind) backs off a little and tries again from there.
  const bool moved = (cycle.pose.position() - stall_anchor_.position()).norm() > 0.1 ||
                     std::abs(wrapToPi(cycle.pose.heading - stall_anchor_.heading)) > 0.3;
  const bool resumed = cycle.now_us - last_follow_us_ > 200'000;  // after a stop or another task
  last_follow_us_ = cycle.now_us;
  const bool trying = result.status == FollowerStatus::Moving || result.status == FollowerStatus::Blocked;
  if (stall_anchor_us_ < 0 || resumed || moved || !trying) {
    stall_anchor_ = cycle.pose;
    stall_anchor_us_ = cycle.now_us;
  } else if (static_cast<double>(cycle.now_us - stall_anchor_us_) * 1e-6 > settings_.stall_timeout_s) {
    countStall(cycle, pointAlongPath(cycle.pose.position(), path_.waypoints, waypoint_index_,
                                     kBlockedPassageLookAheadM));
    advancePassedWaypoints(cycle);  // the escape turns toward the waypoint it will follow
    beginStallEscape(cycle);
    return;
  }
  if (result.status == FollowerStatus::Arrived && waypoint_index_ < last) {
    ++waypoint_index_;
  }
}

void Executive::advancePassedWaypoints(const Cycle& cycle)
{
  const std::vector<Waypoint>& waypoints = path_.waypoints;
  if (waypoints.empty()) {
    return;
  }
  const std::size_t last = waypoints.size() - 1;
  waypoint_index_ = std::min(waypoint_index_, last);
  const auto distance_to = [&cycle, &waypoints](std::size_t index) {
    return (waypoints[index].position - cycle.pose.position()).norm();
  };
  // Where following has stalled again after its escape, a waypoint within the pass radius counts as
  // passed on either side: it is the corner of an obstacle inflated by a disc of the half width (and a
  // layer cell off), where the vehicle's rectangle may not fit facing the next leg, while the follower's
  // cost-to-go to the next waypoint leads round the corner with clearance (tunnel-1 t2 stalled 75 times
  // at one rock corner, each new path leading back to it).
  const bool stalled_here =
      repeated_stall_at_ && (cycle.pose.position() - *repeated_stall_at_).norm() <= kStallSiteRadiusM;
  // Passed: within the tolerance, or within the pass radius and beyond the waypoint, on the next leg's
  // side of the line through it square to that leg.
  const auto passed = [&](std::size_t index) {
    const double distance = distance_to(index);
    if (distance <= settings_.waypoint_tolerance_m) {
      return true;
    }
    const geometry::Point leg = waypoints[index + 1].position - waypoints[index].position;
    return distance <= settings_.waypoint_pass_radius_m &&
           (stalled_here || leg.dot(cycle.pose.position() - waypoints[index].position) > 0.0);
  };
  while (
      waypoint_index_ < last && passed(waypoint_index_) &&
      !(waypoints[waypoint_index_].kind == WaypointKind::Topological && planForWaypoint(waypoint_index_))) {
    ++waypoint_index_;
  }
}

std::vector<geometry::Point> Executive::pathAhead(const Cycle& cycle) const
{
  std::vector<geometry::Point> ahead{cycle.pose.position()};
  for (std::size_t index = waypoint_index_; index < path_.waypoints.size(); ++index) {
    const Waypoint& waypoint = path_.waypoints[index];
    if (waypoint.kind == WaypointKind::Push ||
        (waypoint.kind == WaypointKind::Topological && planForWaypoint(index))) {
      break;
    }
    ahead.push_back(waypoint.position);
  }
  return ahead;
}

void Executive::reportImpassableGap(Cycle& cycle)
{
  const GapReportScope scope = settings_.blocked_passage_on_sight;
  if (scope == GapReportScope::Off || !cycle.obstacles_fresh ||
      (scope == GapReportScope::NearPushedObjects && pushed_objects_left_at_.empty())) {
    return;
  }
  const std::vector<geometry::Point> ahead = pathAhead(cycle);
  const std::optional<ImpassableGap> gap =
      findImpassableGap(common::Span<const geometry::Point>(ahead.data(), ahead.size()), cycle.obstacles,
                        settings_.follower.footprint, settings_.doorway);
  if (!gap) {
    return;
  }
  // Static gaps are left to the follower, which drives round many of them locally (Willow's furniture:
  // each one reported was sealed and changed the route); a pushed object left across a corridor leaves
  // lanes the planner's inflation shows open, each costing a stall series to report.
  if (scope == GapReportScope::NearPushedObjects && !besidePushedObject(*gap)) {
    return;
  }
  // The planner answers within a cycle or two; until then the same path still crosses the gap.
  const geometry::Point middle = 0.5 * (gap->first_post + gap->second_post);
  if (gap_reported_us_ >= 0 && (middle - gap_reported_at_).norm() < kStallSiteRadiusM &&
      static_cast<double>(cycle.now_us - gap_reported_us_) * 1e-6 < settings_.gap_report_repeat_s) {
    return;
  }
  gap_reported_at_ = middle;
  gap_reported_us_ = cycle.now_us;
  // Toward the path point 1 m beyond the gap: the planner seals the narrowest free point between the
  // vehicle and it, and a farther point let that land at another gap on a straight line cutting corners.
  BlockedPassage passage;
  passage.goal_id = goal_id_;
  passage.from = cycle.pose.position();
  passage.to = pointAlongPath(passage.from, path_.waypoints, waypoint_index_, gap->along_m + 1.0);
  passage.stalls = 0;
  passage.text = fmt::format(
      "gap of {:.2f} m between ({:.2f}, {:.2f}) and ({:.2f}, {:.2f}), {:.1f} m ahead: narrower than the "
      "vehicle can pass ({:.2f} m)",
      gap->width_m, gap->first_post.x(), gap->first_post.y(), gap->second_post.x(), gap->second_post.y(),
      gap->along_m, passableWidth(settings_.follower.footprint, settings_.doorway));
  cycle.blocked_passage = std::move(passage);
}

bool Executive::besidePushedObject(const ImpassableGap& gap) const
{
  const double radius = settings_.pushed_object.radius_m;
  return std::any_of(pushed_objects_left_at_.begin(), pushed_objects_left_at_.end(),
                     [&gap, radius](const geometry::Point& object) {
                       return (gap.first_post - object).norm() <= radius ||
                              (gap.second_post - object).norm() <= radius;
                     });
}

void Executive::rememberPushedObject(const std::optional<geometry::Point>& observed)
{
  const std::optional<ObjectObservation> expected = pushedObjectEstimate();
  if (!observed && !expected) {
    return;
  }
  // Bounded: only recent pushes matter to the lanes the vehicle is about to drive.
  if (pushed_objects_left_at_.size() >= kPushedObjectsRemembered) {
    pushed_objects_left_at_.erase(pushed_objects_left_at_.begin());
  }
  pushed_objects_left_at_.push_back(observed ? *observed : expected->position);
}

std::optional<Doorway> Executive::doorwayAhead(const Cycle& cycle) const
{
  if (!settings_.doorway.enabled || !cycle.obstacles_fresh) {
    return std::nullopt;
  }
  const std::vector<geometry::Point> ahead = pathAhead(cycle);
  std::optional<Doorway> doorway =
      findDoorway(common::Span<const geometry::Point>(ahead.data(), ahead.size()), cycle.obstacles,
                  settings_.follower.footprint, settings_.doorway);
  if (!doorway) {
    return std::nullopt;
  }
  for (const auto& [centre, until_us] : doorways_given_up_) {
    if (cycle.now_us < until_us && (centre - doorway->centre).norm() < 0.5) {
      return std::nullopt;
    }
  }
  // A goal in the doorway or on its run is the follower's to reach.
  const geometry::Point goal = path_.waypoints.back().position;
  const geometry::Point left(-doorway->heading.y(), doorway->heading.x());
  if (doorway->along(goal) > -settings_.doorway.approach_m &&
      doorway->along(goal) < settings_.doorway.exit_m + settings_.goal_tolerance_m &&
      std::abs(left.dot(goal - doorway->centre)) < doorway->width_m) {
    return std::nullopt;
  }
  return doorway;
}

void Executive::startDoorway(Cycle& cycle, const Doorway& doorway)
{
  doorway_ = doorway;
  const geometry::Point end = doorway.runEnd(settings_.doorway);
  ApproachSettings run = doorwayRunSettings(settings_, drive_);
  doorway_run_.begin({end.x(), end.y(), std::atan2(doorway.heading.y(), doorway.heading.x())}, cycle.pose,
                     run);
  doorway_started_us_ = cycle.now_us;
  anchorMotion(cycle);
  task_ = Task::Doorway;
  stepDoorway(cycle);
}

void Executive::stepDoorway(Cycle& cycle)
{
  const Doorway& doorway = *doorway_;
  const std::string named = fmt::format("doorway at ({:.2f}, {:.2f}), {:.2f} m wide", doorway.centre.x(),
                                        doorway.centre.y(), doorway.width_m);
  const double elapsed_s = static_cast<double>(cycle.now_us - doorway_started_us_) * 1e-6;
  // Standing still (the way to the run's start blocked, the guard stopping the run) gives the run up as
  // surely as the timeout does.
  const bool stuck = standingStill(cycle);
  if (elapsed_s > settings_.doorway.timeout_s || stuck) {
    // Left to the follower for a while; it may yet find its own way through.
    doorways_given_up_.emplace_back(
        doorway.centre, cycle.now_us + static_cast<std::int64_t>(settings_.doorway.retry_after_s * 1e6));
    task_ = Task::Follow;
    stall_anchor_us_ = -1;
    stepFollow(cycle);
    cycle.reason = fmt::format("{} given up after {:.0f} s{}; {}", named, elapsed_s,
                               stuck ? " without moving" : "", cycle.reason);
    return;
  }
  cycle.target = doorway.runEnd(settings_.doorway);
  const ApproachStep result = doorway_run_.step(
      cycle.pose, 0.0, cycle.obstacles, doorwayRunSettings(settings_, drive_), settings_.follower, drive_);
  if (result.phase != ApproachPhase::Done) {
    cycle.desired = result.command;
    cycle.reason = fmt::format("{}: {}", named, result.reason);
    if (result.phase != ApproachPhase::ToStandoff) {
      // Turning square to the door and running through it are not the follower's: the guard checks them.
      guardCommand(cycle, cycle.obstacles);
    }
    return;
  }
  // Through: the waypoints at the posts and on the run are behind.
  const std::size_t last = path_.waypoints.size() - 1;
  while (waypoint_index_ < last) {
    const geometry::Point& position = path_.waypoints[waypoint_index_].position;
    if (doorway.along(position) > settings_.doorway.exit_m + settings_.waypoint_tolerance_m ||
        (position - doorway.centre).norm() > settings_.doorway.approach_m + settings_.doorway.exit_m + 0.5) {
      break;
    }
    ++waypoint_index_;
  }
  doorway_.reset();
  task_ = Task::Follow;
  stall_anchor_us_ = -1;
  stepFollow(cycle);
}

bool Executive::pathCrossesDoorway(const Path& path) const
{
  if (!doorway_ || path.waypoints.size() < 2) {
    return false;
  }
  const geometry::Point left(-doorway_->heading.y(), doorway_->heading.x());
  const geometry::Segment door{doorway_->centre - doorway_->width_m * left,
                               doorway_->centre + doorway_->width_m * left};
  for (std::size_t index = 0; index + 1 < path.waypoints.size(); ++index) {
    if (geometry::segmentsIntersect(
            geometry::Segment{path.waypoints[index].position, path.waypoints[index + 1].position}, door)) {
      return true;
    }
  }
  return false;
}

void Executive::anchorMotion(const Cycle& cycle)
{
  motion_anchor_ = cycle.pose;
  motion_anchor_us_ = cycle.now_us;
}

bool Executive::standingStill(const Cycle& cycle)
{
  if ((cycle.pose.position() - motion_anchor_.position()).norm() > 0.1 ||
      std::abs(wrapToPi(cycle.pose.heading - motion_anchor_.heading)) > 0.3) {
    anchorMotion(cycle);
  }
  return static_cast<double>(cycle.now_us - motion_anchor_us_) * 1e-6 > 2.0 * settings_.stall_timeout_s;
}

void Executive::countStall(Cycle& cycle, const geometry::Point& target)
{
  const geometry::Point position = cycle.pose.position();
  if (last_stall_at_ && (position - *last_stall_at_).norm() <= kStallSiteRadiusM) {
    repeated_stall_at_ = position;
  }
  last_stall_at_ = position;
  if (stalls_at_site_ == 0 || (position - stall_site_).norm() > kStallSiteRadiusM ||
      (target - stall_site_target_).norm() > kStallSiteRadiusM) {
    stall_site_ = position;
    stall_site_target_ = target;
    stalls_at_site_ = 0;
  }
  ++stalls_at_site_;
  if (settings_.blocked_passage_stalls <= 0 || stalls_at_site_ < settings_.blocked_passage_stalls) {
    return;
  }
  // The local planner cannot get the vehicle through what the global path takes for a passage (a gap the
  // planner's inflation leaves open but the footprint does not fit): the planner must route around it.
  BlockedPassage passage;
  passage.goal_id = goal_id_;
  passage.from = position;
  passage.to = target;
  passage.stalls = stalls_at_site_;
  passage.text =
      fmt::format("stalled {} times within {:.1f} m of ({:.2f}, {:.2f}) toward ({:.2f}, {:.2f})",
                  stalls_at_site_, kStallSiteRadiusM, position.x(), position.y(), target.x(), target.y());
  cycle.blocked_passage = std::move(passage);
  stalls_at_site_ = 0;
}

void Executive::giveUpUnreachableContact(Cycle& cycle, const std::string& contact)
{
  // The contact cannot be reached (the stand-off point boxed in, the guard stopping the creep).
  giveUpPlan(cycle, fmt::format("object {}: {} not reached: no motion for {:.1f} s on the way to it",
                                active_plan_.object_id, contact, 2.0 * settings_.stall_timeout_s));
}

void Executive::giveUpPlan(Cycle& cycle, const std::string& text)
{
  // The plan costs more than planned, without bound. Algorithm 2's answer: tell the planner, wait for
  // its replan.
  AffordanceEvent event;
  event.object_id = active_plan_.object_id;
  event.pushable = false;
  event.planned_cost = active_plan_.expected_cost;
  event.measured_cost = active_plan_.expected_cost;
  event.reason = AffordanceReason::CostHigher;
  event.text = text;
  cycle.affordance = event;
  task_ = Task::ReplanWait;
  replan_requested_us_ = cycle.now_us;
  ++replans_;
  task_reason_ = fmt::format("waiting for replan: {}", event.text);
  cycle.reason = task_reason_;
  cycle.desired = {};
}

void Executive::stepApproach(Cycle& cycle)
{
  cycle.target = active_plan_.contact_pose.position();
  cycle.target_object_id = active_plan_.object_id;
  const common::Span<const geometry::Point> obstacles = objectFreeObstacles(cycle);
  bool standing_still = standingStill(cycle);
  if (standing_still && approach_.joinLane(cycle.pose, settings_.approach)) {
    // Stuck on the way to the stand-off point, already in the push lane (a corridor too narrow to turn
    // in): creep along it, no turn on the spot. Its own stall clock starts now.
    anchorMotion(cycle);
    standing_still = false;
  }
  if (standing_still && approach_.phase() == ApproachPhase::ToStandoff &&
      approach_escaped_object_ != active_plan_.object_id) {
    // Stuck on the collision-free leg (e.g. turned toward a side door by a path that flipped, facing a
    // wall): that says nothing about the object yet. Escape once as following does (back off, turn to
    // the way on); following then starts the approach again.
    approach_escaped_object_ = active_plan_.object_id;
    beginStallEscape(cycle);
    return;
  }
  if (standing_still) {
    giveUpUnreachableContact(cycle, "contact");
    return;
  }
  if (backUpToAlign(cycle, obstacles)) {
    return;
  }
  const ApproachStep result =
      approach_.step(cycle.pose, cycle.force_n, obstacles, settings_.approach, settings_.follower, drive_);
  if (result.phase != ApproachPhase::Done) {
    cycle.desired = result.command;
    cycle.reason = fmt::format("object {}: {}", active_plan_.object_id, result.reason);
    if (result.phase != ApproachPhase::ToStandoff) {
      // Aligning and creeping ignore obstacles (the object must be touched): the guard still stops
      // them for anything that is not the object.
      guardCommand(cycle, obstacles);
    }
    return;
  }
  push_control_index_ = 0;
  approach_escaped_object_.reset();
  push_phase_ = PushPhase::Pushing;
  anchorMotion(cycle);
  tracker_.begin(active_plan_);
  const bool jammed_before = std::find(jammed_objects_.begin(), jammed_objects_.end(),
                                       active_plan_.object_id) != jammed_objects_.end();
  tactile_.begin(active_plan_, max_push_force_n_, jammed_before);
  task_ = Task::Push;
  stepPush(cycle);
}

bool Executive::backUpToAlign(Cycle& cycle, common::Span<const geometry::Point> obstacles)
{
  const double lane_heading = approach_.contact().heading;
  if (approach_.phase() != ApproachPhase::Align ||
      std::abs(wrapToPi(lane_heading - cycle.pose.heading)) <= settings_.approach.heading_tolerance_rad ||
      freeTurn(cycle.pose, lane_heading, obstacles, kAlignTurnMarginM)) {
    return false;
  }
  if (!align_backup_start_) {
    align_backup_start_ = cycle.pose.position();
  }
  const double backed = (cycle.pose.position() - *align_backup_start_).norm();
  if (backed >= kAlignBackUpM) {
    return false;  // turn as far as the guard lets it; standing still there gives the contact up
  }
  const std::string turning = cycle.reason;
  cycle.desired = {-settings_.pusher.reverse_speed, 0.0};
  cycle.reason = fmt::format("object {}: approach: backing up to turn to the lane's heading, {:.2f} m",
                             active_plan_.object_id, backed);
  guardCommand(cycle, obstacles);
  if (cycle.desired.isZero()) {
    cycle.reason = turning;
    return false;
  }
  return true;
}

void Executive::stepPush(Cycle& cycle)
{
  cycle.target_object_id = active_plan_.object_id;
  const common::Span<const geometry::Point> obstacles = objectFreeObstacles(cycle);
  const PushStep result = tracker_.step(cycle.pose, cycle.force_n, obstacles, settings_.pusher,
                                        settings_.approach, settings_.follower, drive_);
  push_control_index_ = result.control_index;
  cycle.target = result.control_index < active_plan_.controls.size()
                     ? active_plan_.controls[result.control_index].expected_vehicle_pose.position()
                     : cycle.pose.position();

  std::optional<geometry::Point> object_position;
  if (cycle.inputs.pushed_object && cycle.inputs.pushed_object->value.object_id == active_plan_.object_id &&
      fresh(cycle.now_us, cycle.inputs.pushed_object->utime, settings_.stale.obstacles_s)) {
    object_position = cycle.inputs.pushed_object->value.position;
  }
  std::optional<AffordanceEvent> event = tactile_.update(
      cycle.now_us, cycle.force_n, cycle.pose, object_position, result.expects_contact, settings_.tactile);
  if (event) {
    cycle.affordance = event;
    if (event->reason == AffordanceReason::Jammed) {
      jammed_objects_.push_back(active_plan_.object_id);
    }
    if (!event->pushable || event->reason == AffordanceReason::CostHigher ||
        event->reason == AffordanceReason::Jammed) {
      // Algorithm 2: the plan no longer holds; stop and wait for the planner to use the new estimate.
      rememberPushedObject(object_position);
      task_ = Task::ReplanWait;
      replan_requested_us_ = cycle.now_us;
      ++replans_;
      task_reason_ = fmt::format("waiting for replan: {}", event->text);
      cycle.reason = task_reason_;
      cycle.desired = {};
      return;
    }
    // Cheaper than planned: the push still opens the passage, so it goes on; the planner learns the
    // lower cost from the event.
  }
  if (result.phase != push_phase_) {
    push_phase_ = result.phase;
    anchorMotion(cycle);
  }
  if (result.phase == PushPhase::Switching && standingStill(cycle)) {
    // Between primitives the vehicle drives round the object to its next contact like a first approach,
    // and can be boxed in the same way: one stood 150 s beside a box in a Willow corridor until the run
    // timed out (bench willow t3 at b72a599).
    rememberPushedObject(object_position);
    giveUpUnreachableContact(
        cycle, fmt::format("contact edge {}", active_plan_.controls[result.control_index].contact_edge));
    return;
  }

  if (result.phase == PushPhase::Finished) {
    ++pushes_;
    rememberPushedObject(object_position);
    if (!path_.valid || path_.waypoints.empty()) {
      // The replan during the push found no path: stop until the planner has one.
      adoptPath(path_);
      cycle.reason = fmt::format("push of object {} finished; {}", active_plan_.object_id, task_reason_);
      cycle.desired = {};
      return;
    }
    const int push_waypoint = pushWaypointIndex(active_plan_.object_id);
    waypoint_index_ = push_waypoint >= 0 ? static_cast<std::size_t>(push_waypoint)
                                         : std::min<std::size_t>(1, path_.waypoints.size() - 1);
    task_ = Task::Follow;
    cycle.reason = fmt::format("push of object {} finished", active_plan_.object_id);
    cycle.desired = {};
    return;
  }
  cycle.desired = result.command;
  cycle.reason = fmt::format("object {}: {}", active_plan_.object_id, result.reason);
  guardCommand(cycle, obstacles);
  if (cycle.desired.isZero() && !result.command.isZero() && standingStill(cycle)) {
    // The guard has held the push for twice stall_timeout_s: something beside the object is in the
    // vehicle's way (no force rises, so the tactile monitor says nothing). Without this the vehicle stood
    // there for good (bench Willow t8 beside a door post, docs/executive.md, "Known gap").
    rememberPushedObject(object_position);
    giveUpPlan(cycle, fmt::format("object {}: push held by the guard: no motion for {:.1f} s",
                                  active_plan_.object_id, 2.0 * settings_.stall_timeout_s));
  }
}

void Executive::startObjectPath()
{
  object_path_.clear();
  const std::vector<PushControl>& controls = active_plan_.controls;
  if (controls.empty()) {
    // Nothing to learn the object's place from: assume it just ahead of the bumper at contact.
    const double ahead = settings_.follower.footprint.front_m + settings_.pushed_object.radius_m / 2.0;
    object_path_.push_back(active_plan_.contact_pose.transform(geometry::Point(ahead, 0.0)));
    return;
  }
  const PushControl& first = controls.front();
  if (first.kind == PushControlKind::Push) {
    // The object rides on the bumper during a primitive, so its offset from the vehicle at the end of
    // the first push is its offset at contact too.
    const geometry::Point offset =
        first.expected_vehicle_pose.inverseTransform(first.expected_object_pose.position());
    object_path_.push_back(active_plan_.contact_pose.transform(offset));
  } else {
    object_path_.push_back(first.expected_object_pose.position());  // a contact switch leaves it in place
  }
  for (const PushControl& control : controls) {
    object_path_.push_back(control.expected_object_pose.position());
  }
}

std::optional<ObjectObservation> Executive::pushedObjectEstimate() const
{
  if ((task_ != Task::Approach && task_ != Task::Push) || object_path_.empty()) {
    return std::nullopt;
  }
  // object_path_[k] is where primitive k starts (before the push: index 0).
  const std::size_t index = task_ == Task::Push ? std::min(push_control_index_, object_path_.size() - 1) : 0;
  return ObjectObservation{active_plan_.object_id, object_path_[index]};
}

common::Span<const geometry::Point> Executive::objectFreeObstacles(const Cycle& cycle)
{
  if (!cycle.obstacles_fresh) {
    return cycle.obstacles;
  }
  const double radius = settings_.pushed_object.radius_m;
  std::optional<geometry::Point> observed;
  if (cycle.inputs.pushed_object && cycle.inputs.pushed_object->value.object_id == active_plan_.object_id &&
      fresh(cycle.now_us, cycle.inputs.pushed_object->utime, settings_.stale.obstacles_s)) {
    observed = cycle.inputs.pushed_object->value.position;
  }
  const auto on_object = [this, radius, &observed](const geometry::Point& point) {
    if (observed && (point - *observed).norm() <= radius) {
      return true;
    }
    if (object_path_.size() == 1) {
      return (point - object_path_.front()).norm() <= radius;
    }
    for (std::size_t index = 1; index < object_path_.size(); ++index) {
      if (geometry::distanceToSegment(
              point, geometry::Segment{object_path_[index - 1], object_path_[index]}) <= radius) {
        return true;
      }
    }
    return false;
  };
  object_free_obstacles_.clear();
  for (const geometry::Point& point : cycle.obstacles) {
    if (!on_object(point)) {
      object_free_obstacles_.push_back(point);
    }
  }
  return common::Span<const geometry::Point>(object_free_obstacles_.data(), object_free_obstacles_.size());
}

void Executive::guardCommand(Cycle& cycle, common::Span<const geometry::Point> obstacles) const
{
  const VelocityCommand command = cycle.desired;
  if (!cycle.obstacles_fresh || command.isZero()) {
    return;
  }
  const Footprint& footprint = settings_.follower.footprint;
  const double horizon_s = settings_.pushed_object.guard_horizon_s;
  const double clearance = settings_.pushed_object.guard_clearance_m;
  const double time_step_s = std::min(settings_.follower.time_step_s, horizon_s);
  const int steps = static_cast<int>(std::floor(horizon_s / time_step_s + 1e-9));
  // Points farther than this from the reference point cannot come within the clearance in the horizon.
  const double reach = footprint.bodyCentre().norm() + footprint.circumradius() +
                       std::abs(command.linear) * horizon_s + clearance;
  for (const geometry::Point& point : obstacles) {
    if ((point - cycle.pose.position()).norm() > reach) {
      continue;
    }
    const double distance_now = footprint.distance(cycle.pose, point);
    for (int step = 1; step <= steps; ++step) {
      const geometry::Pose2 ahead =
          integrateArc(cycle.pose, command.linear, command.angular, step * time_step_s);
      const double distance = footprint.distance(ahead, point);
      // Only closing in counts, so the vehicle can always back away from something already near.
      if (distance < clearance - kGuardRoundingM && distance < distance_now - kGuardRoundingM) {
        cycle.desired = {};
        cycle.reason +=
            fmt::format(" (stopped: obstacle at ({:.2f}, {:.2f}) in the way)", point.x(), point.y());
        return;
      }
    }
  }
}

void Executive::guardedEscape(Cycle& cycle, double linear,
                              common::Span<const geometry::Point> obstacles) const
{
  const std::string reason = cycle.reason;
  cycle.desired = {linear, 0.0};
  guardCommand(cycle, obstacles);
  if (!cycle.desired.isZero()) {
    return;
  }
  const std::string stopped = cycle.reason;
  // A gentle arc (half the approach's turning rate) before a tight one (its full rate), each turning first
  // the way the follower wants to face.
  const std::optional<double> wanted = stallTurnHeading(cycle);
  const double first_sign = wanted && wrapToPi(*wanted - cycle.pose.heading) < 0.0 ? -1.0 : 1.0;
  const double max_rate = settings_.approach.control.max_angular_velocity;
  for (const double rate : {0.5 * max_rate, max_rate}) {
    for (const double sign : {first_sign, -first_sign}) {
      cycle.reason = reason;
      cycle.desired = {linear, sign * rate};
      guardCommand(cycle, obstacles);
      if (!cycle.desired.isZero()) {
        cycle.reason +=
            fmt::format(" (on an arc turning {}: straight is blocked)", sign > 0.0 ? "left" : "right");
        return;
      }
    }
  }
  cycle.reason = stopped;
  cycle.desired = {};
}

double Executive::freeStraightDistance(const geometry::Pose2& pose, double sign,
                                       common::Span<const geometry::Point> obstacles, double limit_m) const
{
  const Footprint& footprint = settings_.follower.footprint;
  const double clearance = settings_.pushed_object.guard_clearance_m;
  constexpr double kStepM = 0.02;
  const double reach = footprint.bodyCentre().norm() + footprint.circumradius() + limit_m + clearance;
  double free_m = limit_m;
  for (const geometry::Point& point : obstacles) {
    if ((point - pose.position()).norm() > reach) {
      continue;
    }
    const double distance_now = footprint.distance(pose, point);
    for (int step = 1; step * kStepM < free_m + 1e-9; ++step) {
      const double travel = step * kStepM;
      const geometry::Pose2 moved = integrateArc(pose, sign, 0.0, travel);
      const double distance = footprint.distance(moved, point);
      if (distance < clearance && distance < distance_now) {
        free_m = travel - kStepM;
        break;
      }
    }
  }
  return std::max(free_m, 0.0);
}

bool Executive::freeTurn(const geometry::Pose2& pose, double heading,
                         common::Span<const geometry::Point> obstacles, double margin_m) const
{
  const Footprint& footprint = settings_.follower.footprint;
  const double clearance = settings_.pushed_object.guard_clearance_m + margin_m;
  constexpr double kStepRad = 0.05;
  const double turn = wrapToPi(heading - pose.heading);
  const int steps = static_cast<int>(std::ceil(std::abs(turn) / kStepRad));
  const double reach = footprint.bodyCentre().norm() + footprint.circumradius() + clearance;
  for (const geometry::Point& point : obstacles) {
    if ((point - pose.position()).norm() > reach) {
      continue;
    }
    const double distance_now = footprint.distance(pose, point);
    for (int step = 1; step <= steps; ++step) {
      const geometry::Pose2 turned{pose.x, pose.y, pose.heading + turn * step / steps};
      const double distance = footprint.distance(turned, point);
      if (distance < clearance && distance < distance_now) {
        return false;
      }
    }
  }
  return true;
}

std::optional<FollowerResult> Executive::reverseTowardWaypoint(const Cycle& cycle) const
{
  if (!has_path_ || path_.waypoints.empty()) {
    return std::nullopt;
  }
  const geometry::Point& target =
      path_.waypoints[std::min(waypoint_index_, path_.waypoints.size() - 1)].position;
  const geometry::Point offset = target - cycle.pose.position();
  const double bearing = std::atan2(offset.y(), offset.x());
  if (std::abs(wrapToPi(bearing - cycle.pose.heading)) <= kPi / 2.0) {
    return std::nullopt;
  }
  FollowerResult result =
      followReversing(cycle.pose, target, cycle.obstacles, settings_.follower,
                      settings_.pushed_object.guard_clearance_m, settings_.pusher.reverse_speed, drive_);
  if (result.status != FollowerStatus::Moving || result.progress_m <= kReversingProgressM) {
    return std::nullopt;
  }
  return result;
}

std::optional<double> Executive::stallTurnHeading(const Cycle& cycle) const
{
  if (!has_path_ || path_.waypoints.empty()) {
    return std::nullopt;
  }
  const std::size_t last = path_.waypoints.size() - 1;
  const std::size_t index = std::min(waypoint_index_, last);
  const std::optional<double> heading =
      facingDirection(cycle.pose, path_.waypoints[index].position, index == last, cycle.obstacles,
                      settings_.follower, drive_);
  if (!heading || std::abs(wrapToPi(*heading - cycle.pose.heading)) <= kStallTurnToleranceRad) {
    return std::nullopt;
  }
  return heading;
}

void Executive::beginStallEscape(Cycle& cycle)
{
  task_ = Task::BackOff;
  backoff_after_stall_ = true;
  stall_escape_sign_ = 0.0;
  stall_reversing_ = false;
  stall_turn_heading_.reset();
  backoff_start_.reset();
  stall_anchor_us_ = -1;
  stepBackOff(cycle);
}

void Executive::stepBackOff(Cycle& cycle)
{
  if (!backoff_after_stall_) {
    cycle.target_object_id = active_plan_.object_id;
  }
  if (!backoff_start_) {
    backoff_start_ = cycle.pose.position();
  }
  const double travelled = (cycle.pose.position() - *backoff_start_).norm();
  const double release_m = settings_.pusher.release_m;
  bool escape_further = false;
  if (backoff_after_stall_ && travelled >= release_m && !stall_turn_heading_) {
    // Face the way the cost-to-go falls before following again, when that takes a turn on the spot; while
    // the turn is not free, go on straight a little further (up to kStallEscapeReleases x release_m).
    const std::optional<double> wanted = stallTurnHeading(cycle);
    if (wanted && freeTurn(cycle.pose, *wanted, cycle.obstacles)) {
      stall_turn_heading_ = wanted;
      stall_turn_since_us_ = cycle.now_us;
    } else if (wanted &&
               travelled < (stall_reversing_ ? kReversingEscapeM : kStallEscapeReleases * release_m)) {
      escape_further = true;
    }
  }
  if (stall_turn_heading_) {
    const double error = wrapToPi(*stall_turn_heading_ - cycle.pose.heading);
    const double turned_s = static_cast<double>(cycle.now_us - stall_turn_since_us_) * 1e-6;
    if (std::abs(error) > kStallTurnToleranceRad && turned_s < kStallTurnTimeoutS) {
      const double rate = std::min(settings_.approach.control.max_angular_velocity,
                                   settings_.approach.control.angular_gain * std::abs(error));
      cycle.desired = {0.0, std::copysign(rate, error)};
      cycle.reason =
          fmt::format("stalled for {:.1f} s: turning on the spot to face the way on, {:.0f} deg to go",
                      settings_.stall_timeout_s, std::abs(error) * 180.0 / kPi);
      guardCommand(cycle, cycle.obstacles);
      if (!cycle.desired.isZero()) {
        return;
      }
    }
  }
  if (travelled >= release_m && !escape_further) {
    task_ = Task::Follow;
    backoff_after_stall_ = false;
    stall_escape_sign_ = 0.0;
    stall_reversing_ = false;
    stall_turn_heading_.reset();
    stall_anchor_us_ = -1;
    stepFollow(cycle);
    return;
  }
  if (backoff_after_stall_) {
    // Straight back, or straight ahead when the back is nearer a wall (wedged by a door post while
    // turning); chosen once, kept until the distance is done.
    // Planned once per cycle: it builds the follower's cost-to-go and samples the whole fan.
    std::optional<FollowerResult> reversing;
    if (stall_escape_sign_ == 0.0) {
      const double limit = settings_.pusher.release_m;
      const double back = freeStraightDistance(cycle.pose, -1.0, cycle.obstacles, limit);
      const double ahead = freeStraightDistance(cycle.pose, 1.0, cycle.obstacles, limit);
      reversing = reverseTowardWaypoint(cycle);
      stall_reversing_ = reversing.has_value();
      stall_escape_sign_ = stall_reversing_ || back >= ahead ? -1.0 : 1.0;
    } else if (stall_reversing_) {
      reversing = reverseTowardWaypoint(cycle);
    }
    if (stall_reversing_) {
      if (reversing) {
        cycle.desired = reversing->command;
        cycle.reason = fmt::format("stalled for {:.1f} s: the way on is behind, {:.2f} m reversed: {}",
                                   settings_.stall_timeout_s, travelled, reversing->reason);
        guardCommand(cycle, cycle.obstacles);
        if (!cycle.desired.isZero()) {
          return;
        }
      }
      // Reversing got nowhere or was guarded: straight back from here, as without a waypoint behind.
      stall_reversing_ = false;
    }
    cycle.reason = fmt::format(
        "stalled for {:.1f} s: {} before following again: {:.2f} of {:.2f} m", settings_.stall_timeout_s,
        stall_escape_sign_ < 0.0 ? "backing up" : "driving ahead", travelled, settings_.pusher.release_m);
    guardedEscape(cycle, stall_escape_sign_ * settings_.pusher.reverse_speed, cycle.obstacles);
    if (cycle.desired.isZero()) {
      // Hemmed in (the chosen way closed): follow again from here rather than wait.
      task_ = Task::Follow;
      backoff_after_stall_ = false;
      stall_escape_sign_ = 0.0;
      stall_reversing_ = false;
      stall_anchor_us_ = -1;
    }
    return;
  }
  cycle.reason = fmt::format("backing away from object {} before following the new path: {:.2f} of {:.2f} m",
                             active_plan_.object_id, travelled, settings_.pusher.release_m);
  guardedEscape(cycle, -settings_.pusher.reverse_speed, objectFreeObstacles(cycle));
  if (cycle.desired.isZero()) {
    // Hemmed in behind: follow the new path from here (its stall recovery tries ahead too) rather than wait.
    task_ = Task::Follow;
    stall_anchor_us_ = -1;
  }
}

void Executive::stepReplanWait(Cycle& cycle)
{
  cycle.target_object_id = active_plan_.object_id;
  const double waited_s = static_cast<double>(cycle.now_us - replan_requested_us_) * 1e-6;
  if (waited_s > settings_.replan_timeout_s) {
    task_ = Task::Halted;
    task_reason_ = fmt::format("no replanned path within {:.1f} s after the affordance update of object {}",
                               settings_.replan_timeout_s, active_plan_.object_id);
  }
  cycle.reason = task_reason_;
}

Output Executive::step(std::int64_t now_us, const Inputs& inputs)
{
  Cycle cycle{now_us, inputs,       {},          0.0, {}, false, {}, {}, geometry::Point::Zero(),
              -1,     std::nullopt, std::nullopt};
  if (inputs.pose) {
    cycle.pose = inputs.pose->value;
  }
  if (inputs.force && !inputs.force->value.faulty) {
    cycle.force_n = inputs.force->value.force_n;
  }
  if (inputs.obstacles && fresh(now_us, inputs.obstacles->utime, settings_.stale.obstacles_s)) {
    cycle.obstacles =
        common::Span<const geometry::Point>(inputs.obstacles->value.data(), inputs.obstacles->value.size());
    cycle.obstacles_fresh = true;
  }

  const std::int32_t stale = staleBits(now_us, inputs);
  absorbPath(inputs);

  const bool active = task_ == Task::Follow || task_ == Task::Doorway || task_ == Task::Approach ||
                      task_ == Task::Push || task_ == Task::ReplanWait || task_ == Task::BackOff;
  const bool e_stopped = inputs.e_stop && inputs.e_stop->value.engaged;
  const bool pose_finite =
      std::isfinite(cycle.pose.x) && std::isfinite(cycle.pose.y) && std::isfinite(cycle.pose.heading);
  const bool halted = e_stopped || (active && (stale != 0 || !pose_finite));
  bool moving = false;
  if (halted) {
    if (e_stopped) {
      cycle.reason =
          fmt::format("e-stop engaged by {}: {}", inputs.e_stop->value.source, inputs.e_stop->value.reason);
    } else if (stale != 0) {
      cycle.reason = fmt::format("stale input: {}", describeStale(stale));
      if ((stale & kStaleMotor) != 0 && inputs.motor && !inputs.motor->value.reason.empty()) {
        cycle.reason += fmt::format(" (motor: {})", inputs.motor->value.reason);
      }
    } else {
      cycle.reason = "pose is not finite";
    }
    if (task_ == Task::Approach || task_ == Task::Push || task_ == Task::Doorway) {
      // The vehicle may have drifted off the plan while stopped: resume by following the (newest) path,
      // which brings it back to the push through the topological waypoint.
      task_ = Task::Follow;
      waypoint_index_ = std::min<std::size_t>(1, path_.waypoints.size() - 1);
    }
  } else {
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
        cycle.reason = task_reason_;
        break;
    }
    moving = task_ == Task::Follow || task_ == Task::Doorway || task_ == Task::Approach ||
             task_ == Task::Push || task_ == Task::BackOff;
    if (!cycle.obstacles_fresh &&
        (task_ == Task::Follow || task_ == Task::Doorway || task_ == Task::Approach)) {
      cycle.reason += " (no fresh obstacle points)";
    }
  }

  const Mode mode = halted ? (e_stopped ? Mode::EStop : Mode::Stop) : modeOf(task_);
  Output output;
  if (moving) {
    const double elapsed_s =
        has_stepped_ ? std::clamp(static_cast<double>(now_us - last_step_us_) * 1e-6, 0.0, 0.2) : 0.0;
    output.command = drive_.limit(cycle.desired, last_command_, elapsed_s);
  }
  output.wheels = drive_.toWheelSpeeds(output.command);
  last_command_ = output.command;
  last_step_us_ = now_us;
  has_stepped_ = true;

  Status& status = output.status;
  status.mode = mode;
  status.goal_id = goal_id_;
  status.waypoint_index = has_path_ ? static_cast<int>(waypoint_index_) : -1;
  status.target = cycle.target;
  status.target_object_id = cycle.target_object_id;
  status.stale = stale;
  status.pushes = pushes_;
  status.replans = replans_;
  status.reason = cycle.reason;
  output.affordance = std::move(cycle.affordance);
  output.blocked_passage = std::move(cycle.blocked_passage);
  output.mode_changed = mode != last_mode_;
  last_mode_ = mode;
  return output;
}

}  // namespace ifar::executive
