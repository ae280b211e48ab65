#include "executive/modes/doorway_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/geometry/segment.hpp"

namespace ifar::executive {
namespace {

/// The approach that drives a doorway's run: to its start, square to the door, along it to its end. No
/// bumper contact ends it.
ApproachSettings runSettings(const ExecutiveSettings& settings, const DifferentialDrive& drive)
{
  const DoorwaySettings& doorway = settings.doorway;
  ApproachSettings run = settings.approach;
  // Nothing is pushed: the turn square to the door may use the vehicle's own turn rate.
  run.control.max_angular_velocity = drive.maxAngularVelocity();
  run.standoff_m = doorway.approach_m + doorway.exit_m;
  run.creep_speed = doorway.speed;
  run.contact_tolerance_m = doorway.run_end_tolerance_m;
  run.contact_force_n = std::numeric_limits<double>::infinity();
  // Arriving at the run's start at speed and nearly on its heading, the lane tracker turns the rest while
  // moving.
  run.stop_at_standoff = false;
  run.heading_tolerance_rad = doorway.run_heading_tolerance_rad;
  run.standoff_tolerance_m = std::max(run.standoff_tolerance_m, doorway.run_start_tolerance_m);
  return run;
}

}  // namespace

DoorwayRun::DoorwayRun(const ExecutiveSettings& settings, const DifferentialDrive& drive)
    : settings_(settings.doorway),
      run_settings_(runSettings(settings, drive)),
      follower_(settings.follower),
      drive_(drive),
      goal_tolerance_m_(settings.goal_tolerance_m),
      waypoint_tolerance_m_(settings.waypoint_tolerance_m),
      standstill_(settings.stall_recovery.still_distance_m, settings.stall_recovery.still_turn_rad,
                  settings.stall_recovery.standstill_timeout_s)
{
}

std::optional<Doorway> DoorwayRun::find(common::Span<const geometry::Point> ahead,
                                        const geometry::Point& goal, const CycleView& view) const
{
  if (!settings_.enabled || !view.obstacles_fresh) {
    return std::nullopt;
  }
  std::optional<Doorway> doorway = findDoorway(ahead, view.obstacles, follower_.footprint, settings_);
  if (!doorway) {
    return std::nullopt;
  }
  for (const auto& [centre, until_us] : given_up_) {
    if (view.now_us < until_us && (centre - doorway->centre).norm() < settings_.retry_radius_m) {
      return std::nullopt;
    }
  }
  const geometry::Point left(-doorway->heading.y(), doorway->heading.x());
  if (doorway->along(goal) > -settings_.approach_m &&
      doorway->along(goal) < settings_.exit_m + goal_tolerance_m_ &&
      std::abs(left.dot(goal - doorway->centre)) < doorway->width_m) {
    return std::nullopt;
  }
  return doorway;
}

void DoorwayRun::start(const Doorway& doorway, const CycleView& view)
{
  doorway_ = doorway;
  const geometry::Point end = doorway.runEnd(settings_);
  run_.begin({end.x(), end.y(), std::atan2(doorway.heading.y(), doorway.heading.x())}, view.pose,
             run_settings_);
  started_us_ = view.now_us;
  standstill_.anchor(view);
}

DoorwayRun::Step DoorwayRun::step(const CycleView& view, const CollisionGuard& guard, MotionRequest& request)
{
  const Doorway& doorway = *doorway_;
  const std::string named = fmt::format("doorway at ({:.2f}, {:.2f}), {:.2f} m wide", doorway.centre.x(),
                                        doorway.centre.y(), doorway.width_m);
  const double elapsed_s = static_cast<double>(view.now_us - started_us_) * 1e-6;
  // Standing still (the way to the run's start blocked, the guard stopping the run) gives the run up as
  // surely as the timeout does.
  const bool stuck = standstill_.standingStill(view);
  if (elapsed_s > settings_.timeout_s || stuck) {
    // Left to the follower for a while; it may yet find its own way through.
    given_up_.emplace_back(doorway.centre,
                           view.now_us + static_cast<std::int64_t>(settings_.retry_after_s * 1e6));
    return {Progress::GivenUp,
            fmt::format("{} given up after {:.0f} s{}", named, elapsed_s, stuck ? " without moving" : "")};
  }
  const ApproachStep result = run_.step(view.pose, 0.0, view.obstacles, run_settings_, follower_, drive_);
  if (result.phase == ApproachPhase::Done) {
    return {Progress::Through, {}};
  }
  request.command = result.command;
  request.reason = fmt::format("{}: {}", named, result.reason);
  if (result.phase != ApproachPhase::ToStandoff) {
    // Turning square to the door and running through it are not the follower's: the guard checks them.
    guard.stop(view.pose, view.obstacles, request);
  }
  return {Progress::Driving, {}};
}

bool DoorwayRun::keepsGoingFor(const Path& path) const
{
  return run_.phase() == ApproachPhase::Creep || crosses(path);
}

bool DoorwayRun::leftBehind(const geometry::Point& waypoint) const
{
  return !(doorway_->along(waypoint) > settings_.exit_m + waypoint_tolerance_m_ ||
           (waypoint - doorway_->centre).norm() >
               settings_.approach_m + settings_.exit_m + settings_.passed_margin_m);
}

bool DoorwayRun::crosses(const Path& path) const
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

}  // namespace ifar::executive
