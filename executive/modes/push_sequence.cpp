#include "executive/modes/push_sequence.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/geometry/segment.hpp"
#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

PushSequence::PushSequence(const ExecutiveSettings& settings, const common::VehicleSettings& vehicle,
                           const DifferentialDrive& drive)
    : settings_(settings),
      drive_(drive),
      max_push_force_n_(std::min(vehicle.maxPushForce(), vehicle.force_sensor_range_n)),
      standstill_(settings.stall_recovery.still_distance_m, settings.stall_recovery.still_turn_rad,
                  settings.stall_recovery.standstill_timeout_s)
{
}

void PushSequence::begin(const PushPlan& plan, const CycleView& view)
{
  plan_ = plan;
  startObjectPath();
  approach_.begin(plan_.contact_pose, view.pose, settings_.approach);
  align_backup_start_.reset();
  standstill_.anchor(view);
}

PushSequence::Step PushSequence::approach(const CycleView& view, const CollisionGuard& guard,
                                          MotionRequest& request)
{
  Step step;
  step.target = plan_.contact_pose.position();
  const common::Span<const geometry::Point> obstacles = objectFreeObstacles(view);
  bool standing_still = standstill_.standingStill(view);
  if (standing_still && approach_.joinLane(view.pose, settings_.approach)) {
    // Stuck on the way to the stand-off point, already in the push lane (a corridor too narrow to turn
    // in): creep along it, no turn on the spot. Its own stall clock starts now.
    standstill_.anchor(view);
    standing_still = false;
  }
  if (standing_still && approach_.phase() == ApproachPhase::ToStandoff &&
      escaped_object_ != plan_.object_id) {
    // Stuck on the collision-free leg (e.g. turned toward a side door by a path that flipped, facing a
    // wall): that says nothing about the object yet. Escape once as following does (back off, turn to
    // the way on); following then starts the approach again.
    escaped_object_ = plan_.object_id;
    step.next = Next::Escape;
    return step;
  }
  if (standing_still) {
    step.next = Next::WaitForReplan;
    step.affordance = unreachable("contact");
    return step;
  }
  if (backUpToAlign(view, obstacles, guard, request)) {
    return step;
  }
  const ApproachStep result =
      approach_.step(view.pose, view.force_n, obstacles, settings_.approach, settings_.follower, drive_);
  if (result.phase != ApproachPhase::Done) {
    request.command = result.command;
    request.reason = fmt::format("object {}: {}", plan_.object_id, result.reason);
    if (result.phase != ApproachPhase::ToStandoff) {
      // Aligning and creeping ignore obstacles (the object must be touched): the guard still stops
      // them for anything that is not the object.
      guard.stop(view.pose, obstacles, request);
    }
    return step;
  }
  startPush(view);
  step.next = Next::Push;
  return step;
}

void PushSequence::startPush(const CycleView& view)
{
  control_index_ = 0;
  escaped_object_.reset();
  phase_ = PushPhase::Pushing;
  standstill_.anchor(view);
  tracker_.begin(plan_);
  const bool jammed_before =
      std::find(jammed_objects_.begin(), jammed_objects_.end(), plan_.object_id) != jammed_objects_.end();
  tactile_.begin(plan_, max_push_force_n_, jammed_before);
}

bool PushSequence::backUpToAlign(const CycleView& view, common::Span<const geometry::Point> obstacles,
                                 const CollisionGuard& guard, MotionRequest& request)
{
  const double lane_heading = approach_.contact().heading;
  if (approach_.phase() != ApproachPhase::Align ||
      std::abs(wrapToPi(lane_heading - view.pose.heading)) <= settings_.approach.heading_tolerance_rad ||
      guard.freeTurn(view.pose, lane_heading, obstacles, settings_.approach.align_turn_margin_m)) {
    return false;
  }
  if (!align_backup_start_) {
    align_backup_start_ = view.pose.position();
  }
  const double backed = (view.pose.position() - *align_backup_start_).norm();
  if (backed >= settings_.approach.align_backup_m) {
    return false;  // turn as far as the guard lets it; standing still there gives the contact up
  }
  const std::string turning = request.reason;
  request.command = {-settings_.pusher.reverse_speed, 0.0};
  request.reason = fmt::format("object {}: approach: backing up to turn to the lane's heading, {:.2f} m",
                               plan_.object_id, backed);
  guard.stop(view.pose, obstacles, request);
  if (request.command.isZero()) {
    request.reason = turning;
    return false;
  }
  return true;
}

PushSequence::Step PushSequence::push(const CycleView& view, const CollisionGuard& guard,
                                      MotionRequest& request)
{
  const common::Span<const geometry::Point> obstacles = objectFreeObstacles(view);
  const PushStep result = tracker_.step(view.pose, view.force_n, obstacles, settings_.pusher,
                                        settings_.approach, settings_.follower, drive_);
  control_index_ = result.control_index;
  Step step;
  step.target = result.control_index < plan_.controls.size()
                    ? plan_.controls[result.control_index].expected_vehicle_pose.position()
                    : view.pose.position();
  const std::optional<geometry::Point> observed = observedObject(view);
  step.affordance = tactileVerdict(view, result, observed);
  if (step.affordance &&
      (!step.affordance->pushable || step.affordance->reason == AffordanceReason::CostHigher ||
       step.affordance->reason == AffordanceReason::Jammed)) {
    // Algorithm 2: the plan no longer holds; stop and wait for the planner to use the new estimate.
    step.object_left_at = observed ? observed : objectEstimate(true);
    step.next = Next::WaitForReplan;
    return step;
  }
  // Cheaper than planned: the push still opens the passage, so it goes on; the planner learns the lower
  // cost from the event.
  if (result.phase != phase_) {
    phase_ = result.phase;
    standstill_.anchor(view);
  }
  if (result.phase == PushPhase::Switching && standstill_.standingStill(view)) {
    // Between primitives the vehicle drives round the object to its next contact like a first approach,
    // and can be boxed in the same way.
    step.object_left_at = observed ? observed : objectEstimate(true);
    step.affordance =
        unreachable(fmt::format("contact edge {}", plan_.controls[result.control_index].contact_edge));
    step.next = Next::WaitForReplan;
    return step;
  }
  if (result.phase == PushPhase::Finished) {
    step.object_left_at = observed ? observed : objectEstimate(true);
    step.next = Next::Finished;
    return step;
  }
  request.command = result.command;
  request.reason = fmt::format("object {}: {}", plan_.object_id, result.reason);
  guard.stop(view.pose, obstacles, request);
  if (request.command.isZero() && !result.command.isZero() && standstill_.standingStill(view)) {
    // The guard has held the push for the standstill timeout: something beside the object is in the
    // vehicle's way (no force rises, so the tactile monitor says nothing). Without this the vehicle
    // stood there for good.
    step.object_left_at = observed ? observed : objectEstimate(true);
    step.affordance = notReached(fmt::format("object {}: push held by the guard: no motion for {:.1f} s",
                                             plan_.object_id, settings_.stall_recovery.standstill_timeout_s));
    step.next = Next::WaitForReplan;
  }
  return step;
}

std::optional<AffordanceEvent> PushSequence::tactileVerdict(const CycleView& view, const PushStep& tracked,
                                                            const std::optional<geometry::Point>& observed)
{
  const std::optional<double> wheel_travel =
      view.wheels ? std::optional<double>(view.wheels->travel_m) : std::nullopt;
  std::optional<AffordanceEvent> event =
      tactile_.update(view.now_us, view.force_n, view.pose, wheel_travel, observed, tracked.expects_contact,
                      settings_.tactile);
  if (event && event->reason == AffordanceReason::Jammed) {
    jammed_objects_.push_back(plan_.object_id);
  }
  return event;
}

AffordanceEvent PushSequence::notReached(const std::string& text) const
{
  // Only force evidence says an object cannot be pushed: standing still short of it says that the vehicle
  // could not get there, which the planner answers by trying again (another contact, later) instead.
  AffordanceEvent event;
  event.object_id = plan_.object_id;
  event.pushable = true;
  event.planned_cost = plan_.expected_cost;
  event.measured_cost = plan_.expected_cost;
  event.reason = AffordanceReason::ContactNotReached;
  event.text = text;
  return event;
}

AffordanceEvent PushSequence::unreachable(const std::string& contact) const
{
  // The contact cannot be reached (the stand-off point boxed in, the guard stopping the creep).
  return notReached(fmt::format("object {}: {} not reached: no motion for {:.1f} s on the way to it",
                                plan_.object_id, contact, settings_.stall_recovery.standstill_timeout_s));
}

void PushSequence::startObjectPath()
{
  object_path_.clear();
  const std::vector<PushControl>& controls = plan_.controls;
  if (controls.empty()) {
    // Nothing to learn the object's place from: assume it just ahead of the bumper at contact.
    const double ahead = settings_.follower.footprint.front_m + settings_.pushed_object.radius_m / 2.0;
    object_path_.push_back(plan_.contact_pose.transform(geometry::Point(ahead, 0.0)));
    return;
  }
  const PushControl& first = controls.front();
  if (first.kind == PushControlKind::Push) {
    // The object rides on the bumper during a primitive, so its offset from the vehicle at the end of
    // the first push is its offset at contact too.
    const geometry::Point offset =
        first.expected_vehicle_pose.inverseTransform(first.expected_object_pose.position());
    object_path_.push_back(plan_.contact_pose.transform(offset));
  } else {
    object_path_.push_back(first.expected_object_pose.position());  // a contact switch leaves it in place
  }
  for (const PushControl& control : controls) {
    object_path_.push_back(control.expected_object_pose.position());
  }
}

std::optional<geometry::Point> PushSequence::objectEstimate(bool pushing) const
{
  if (object_path_.empty()) {
    return std::nullopt;
  }
  // object_path_[k] is where primitive k starts (before the push: index 0).
  return object_path_[pushing ? std::min(control_index_, object_path_.size() - 1) : 0];
}

std::optional<geometry::Point> PushSequence::observedObject(const CycleView& view) const
{
  if (view.pushed_object && view.pushed_object->object_id == plan_.object_id) {
    return view.pushed_object->position;
  }
  return std::nullopt;
}

common::Span<const geometry::Point> PushSequence::objectFreeObstacles(const CycleView& view)
{
  if (!view.obstacles_fresh) {
    return view.obstacles;
  }
  const double radius = settings_.pushed_object.radius_m;
  const std::optional<geometry::Point> observed = observedObject(view);
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
  object_free_.clear();
  for (const geometry::Point& point : view.obstacles) {
    if (!on_object(point)) {
      object_free_.push_back(point);
    }
  }
  return common::Span<const geometry::Point>(object_free_.data(), object_free_.size());
}

}  // namespace ifar::executive
