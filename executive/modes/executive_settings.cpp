#include "executive/modes/executive_settings.hpp"

#include <stdexcept>
#include <string>

namespace ifar::executive {
namespace {

using Range = common::ParameterRange;
using Table = common::ParameterTable<ExecutiveSettings>;

void addTopLevel(Table& table)
{
  using S = ExecutiveSettings;
  table
      .add(
          "stale_after_s.pose", [](auto& s) -> auto& { return s.stale.pose_s; }, "s", Range::positive(),
          "POSE older than this is stale: zero velocity on the next cycle (POSE arrives at 50 Hz)")
      .add(
          "stale_after_s.path", [](auto& s) -> auto& { return s.stale.path_s; }, "s", Range::positive(),
          "GLOBAL_PATH older than this is stale: a dead planner stops the vehicle (it is resent at 20 Hz)")
      .add(
          "stale_after_s.force", [](auto& s) -> auto& { return s.stale.force_s; }, "s", Range::positive(),
          "FORCE older than this is stale (it arrives at 100 Hz)")
      .add(
          "stale_after_s.motor", [](auto& s) -> auto& { return s.stale.motor_s; }, "s", Range::positive(),
          "MOTOR_STATUS older than this is stale (it arrives at 10 Hz)")
      .add(
          "stale_after_s.obstacles", [](auto& s) -> auto& { return s.stale.obstacles_s; }, "s",
          Range::positive(),
          "obstacle points older than this are stale (their stamp is the newest packet's): a silent lidar "
          "stops the vehicle")
      .add(
          "stale_after_s.odometry", [](auto& s) -> auto& { return s.stale.odometry_s; }, "s",
          Range::positive(),
          "ODOMETRY older than this is not used: push progress and stalls are judged on the pose alone "
          "(it arrives at 100 Hz)")
      .add("waypoint_tolerance_m", &S::waypoint_tolerance_m, "m", Range::positive(),
           "an intermediate waypoint counts as passed within this distance")
      .add(
          "waypoint_pass_radius_m", &S::waypoint_pass_radius_m, "m", Range::positive(),
          "... and within this once the vehicle is beyond it: a door post's inflated corner is closer to the "
          "post than the vehicle gets")
      .add("goal_tolerance_m", &S::goal_tolerance_m, "m", Range::positive(),
           "the goal counts as reached (the vehicle stops) within this distance")
      .add("push_switch_radius_m", &S::push_switch_radius_m, "m", Range::positive(),
           "r in Algorithm 2: switch to the push plan this close to a topological waypoint")
      .add("arrived_hold_m", &S::arrived_hold_m, "m", Range::nonNegative(),
           "a new plan to the same goal within goal_tolerance_m + this keeps the vehicle arrived (it coasts)")
      .add("replan_timeout_s", &S::replan_timeout_s, "s", Range::positive(),
           "after an affordance update, wait this long for a replanned path, then stop")
      .add("stall_timeout_s", &S::stall_timeout_s, "s", Range::positive(),
           "following without moving this long: back off pusher.release_m, turn to the way on, follow again")
      .add("blocked_passage_stalls", &S::blocked_passage_stalls, "", Range::nonNegative(),
           "this many stalls at one site toward one waypoint report the passage blocked (0: never)")
      .add("stall_site_radius_m", &S::stall_site_radius_m, "m", Range::positive(),
           "stalls this close to the first of a series, toward path points this close, are one site")
      .add("blocked_passage_ahead_m", &S::blocked_passage_ahead_m, "m", Range::positive(),
           "a blocked passage is reported toward the path point this far ahead, beyond the vehicle's "
           "inflation")
      .choice(
          "blocked_passage_on_sight", &S::blocked_passage_on_sight,
          {{"off", GapReportScope::Off},
           {"near_pushed_objects", GapReportScope::NearPushedObjects},
           {"everywhere", GapReportScope::Everywhere}},
          "a gap on the path narrower than the vehicle + 2 x doorway.min_clearance_m is reported at once: "
          "never, near where pushes left objects, or everywhere")
      .add("gap_report_repeat_s", &S::gap_report_repeat_s, "s", Range::positive(),
           "the same gap is reported again after this long while the path still crosses it")
      .add(
          "gap_report_beyond_m", &S::gap_report_beyond_m, "m", Range::positive(),
          "a gap is reported toward the path point this far beyond it (farther, the seal can land elsewhere)")
      .add("pushed_objects_remembered", &S::pushed_objects_remembered, "", Range::atLeast(1),
           "where the last this many pushes left their objects (near_pushed_objects)")
      .add("max_cycle_gap_s", &S::max_cycle_gap_s, "s", Range::positive(),
           "speeds grow by at most this long's acceleration between two cycles, however late the second")
      .add("footprint.reference_to_bumper_m", &S::reference_to_bumper_m, "m", Range::positive(),
           "vehicle reference point (the pose) to the bumper face; the rest of length_m is behind");
}

void addStallRecovery(Table& table)
{
  const auto add = [&table](const std::string& key, double StallRecoverySettings::*member, const char* unit,
                            Range range, const std::string& meaning) {
    table.add(
        "stall_recovery." + key, [member](auto& s) -> auto& { return s.stall_recovery.*member; }, unit, range,
        meaning);
  };
  using S = StallRecoverySettings;
  add("still_distance_m", &S::still_distance_m, "m", Range::positive(), "moving less than this ...");
  add("still_turn_rad", &S::still_turn_rad, "rad", Range::positive(),
      "... and turning less than this is getting nowhere (a follower dithering in a door moves less)");
  add("resume_after_s", &S::resume_after_s, "s", Range::positive(),
      "following again after a pause this long (a stop, another task) starts a fresh stall clock");
  add("standstill_timeout_s", &S::standstill_timeout_s, "s", Range::positive(),
      "a doorway run, an approach or a push getting nowhere this long is given up (a push: replan)");
  add("turn_tolerance_rad", &S::turn_tolerance_rad, "rad", Range::positive(),
      "after backing off, turn on the spot to face the way on when it is more than this off ...");
  add("turn_timeout_s", &S::turn_timeout_s, "s", Range::nonNegative(), "... for at most this long");
  add("straight_releases", &S::straight_releases, "", Range::positive(),
      "while that turn is not free, go on straight up to this many pusher.release_m");
  add("reversing_m", &S::reversing_m, "m", Range::nonNegative(),
      "the waypoint behind: reverse along the cost-to-go up to this far (out of a dead end too narrow to "
      "turn)");
  add("reversing_progress_m", &S::reversing_progress_m, "m", Range::nonNegative(),
      "... when a reversing arc lowers the cost-to-go by more than this");
  add("gentle_arc_fraction", &S::gentle_arc_fraction, "", Range::interval(0.0, false, 1.0, true),
      "straight escape guarded: arcs at this fraction of control.max_angular_velocity first, then at all of "
      "it");
}

void addProgress(Table& table)
{
  const auto add = [&table](const std::string& key, double ProgressSettings::*member, const char* unit,
                            Range range, const std::string& meaning) {
    table.add(
        "progress." + key, [member](auto& s) -> auto& { return s.progress.*member; }, unit, range, meaning);
  };
  using S = ProgressSettings;
  add("timeout_s", &S::timeout_s, "s", Range::nonNegative(),
      "no progress toward the goal this long: drop the push or route the vehicle is stuck on, report it (0: "
      "never)");
  add("margin_m", &S::margin_m, "m", Range::nonNegative(),
      "progress: the path left to the goal beats its best by this much ...");
  add("new_ground_m", &S::new_ground_m, "m", Range::nonNegative(),
      "... or the vehicle enters a square of this side it had not been in (0: only the path counts)");
}

void addFollower(Table& table)
{
  const auto add = [&table](const std::string& key, auto member, const char* unit, Range range,
                            const std::string& meaning) {
    table.add(
        "follower." + key, [member](auto& s) -> auto& { return s.follower.*member; }, unit, range, meaning);
  };
  using S = FollowerSettings;
  add("horizon_s", &S::horizon_s, "s", Range::positive(), "how far ahead each sampled arc is checked");
  add("time_step_s", &S::time_step_s, "s", Range::positive(), "footprint checks along each arc");
  add("linear_samples", &S::linear_samples, "", Range::atLeast(1),
      "forward speeds max/n .. max, plus turning on the spot");
  add("angular_samples", &S::angular_samples, "", Range::atLeast(3), "turn rates spread over [-max, max]");
  add("clearance_m", &S::clearance_m, "m", Range::nonNegative(),
      "margin kept between the footprint and obstacle points");
  add("clearance_cap_m", &S::clearance_cap_m, "m", Range::positive(),
      "clearance beyond this earns no more score");
  add("progress_weight", &S::progress_weight, "", Range::nonNegative(),
      "score of progress along the cost-to-go");
  add("heading_weight", &S::heading_weight, "", Range::nonNegative(), "score of facing the way on");
  add("clearance_weight", &S::clearance_weight, "", Range::nonNegative(), "score of clearance");
  add("slow_down_distance_m", &S::slow_down_distance_m, "m", Range::nonNegative(),
      "brakes from top speed over this distance to the goal tolerance (top x sqrt(remaining / this))");
  add("max_linear_velocity", &S::max_linear_velocity, "m/s", Range::positive(),
      "top speed while following; vehicle.yaml's limit applies too");
  add("cell_size_m", &S::cell_size_m, "m", Range::positive(), "obstacle bucket size");
  add("navigation_range_m", &S::navigation_range_m, "m", Range::positive(),
      "half-size limit of the cost-to-go window around the vehicle");
  add("navigation_cell_m", &S::navigation_cell_m, "m", Range::positive(), "cost-to-go cell size");
  add("navigation_proximity_weight", &S::navigation_proximity_weight, "", Range::nonNegative(),
      "cells within half width + clearance_cap_m of an obstacle cost up to 1 + this times their length: the "
      "vehicle keeps to the middle of doors and corridors");
  add("descent_radius_m", &S::descent_radius_m, "m", Range::positive(),
      "the way to face: where the cost-to-go falls fastest on a circle this wide");
  add("turn_in_place_rad", &S::turn_in_place_rad, "rad", Range::between(0.0, 3.141592653589793),
      "facing this far off the way on, turn on the spot; from a third of this on, the forward speed cap "
      "falls linearly to 0: a sharp turn of the path is a pivot, not a loop; 0 = no cap");
}

void addDoorway(Table& table)
{
  const auto add = [&table](const std::string& key, auto member, const char* unit, Range range,
                            const std::string& meaning) {
    table.add(
        "doorway." + key, [member](auto& s) -> auto& { return s.doorway.*member; }, unit, range, meaning);
  };
  using S = DoorwaySettings;
  add("enabled", &S::enabled, "", Range::any(),
      "a door barely wider than the vehicle is driven as a straight run");
  add("max_width_m", &S::max_width_m, "m", Range::positive(),
      "a gap across the path narrower than this (post to post) is a doorway");
  add("look_ahead_m", &S::look_ahead_m, "m", Range::positive(), "the path is searched this far ahead ...");
  add("min_ahead_m", &S::min_ahead_m, "m", Range::nonNegative(),
      "... from this far (less than look_ahead_m)");
  add("approach_m", &S::approach_m, "m", Range::positive(), "the run starts this far before the door ...");
  add("exit_m", &S::exit_m, "m", Range::positive(), "... and ends this far beyond it");
  add("max_skew_rad", &S::max_skew_rad, "rad", Range::nonNegative(),
      "the run may be this far off square to the line between the posts");
  add("min_clearance_m", &S::min_clearance_m, "m", Range::nonNegative(),
      "least distance from the footprint swept along the run to any point");
  add("speed", &S::speed, "m/s", Range::positive(), "speed along the run");
  add("timeout_s", &S::timeout_s, "s", Range::positive(), "a run not done by then is given up ...");
  add("retry_after_s", &S::retry_after_s, "s", Range::nonNegative(),
      "... and that door left to the follower this long");
  add("retry_radius_m", &S::retry_radius_m, "m", Range::nonNegative(),
      "a doorway found within this of a given-up one's centre is the same door");
  add("run_heading_tolerance_rad", &S::run_heading_tolerance_rad, "rad", Range::positive(),
      "arriving at the run's start within this of its heading (and run_start_tolerance_m of it), the lane "
      "tracker turns the rest while moving");
  add("run_start_tolerance_m", &S::run_start_tolerance_m, "m", Range::positive(),
      "see run_heading_tolerance_rad");
  add("run_end_tolerance_m", &S::run_end_tolerance_m, "m", Range::positive(),
      "the run is done this close to its end");
  add("passed_margin_m", &S::passed_margin_m, "m", Range::nonNegative(),
      "through the door, waypoints within approach_m + exit_m + this of its centre are behind");
  add("min_crossing_sine", &S::min_crossing_sine, "", Range::between(0.0, 1.0),
      "a gap line within asin(this) of the path's direction is one the path runs along, not through");
}

void addControlAndApproach(Table& table)
{
  const auto control = [&table](const std::string& key, double PoseControllerSettings::*member,
                                const char* unit, Range range, const std::string& meaning) {
    table.add(
        "control." + key, [member](auto& s) -> auto& { return s.approach.control.*member; }, unit, range,
        meaning);
  };
  using C = PoseControllerSettings;
  control("linear_gain", &C::linear_gain, "1/s", Range::positive(), "speed per metre of distance");
  control("angular_gain", &C::angular_gain, "1/s", Range::positive(),
          "turn rate per radian of heading error");
  control("turn_in_place_error_rad", &C::turn_in_place_error, "rad", Range::positive(),
          "above this heading error, turn before driving");
  control("max_linear_velocity", &C::max_linear_velocity, "m/s", Range::positive(),
          "top speed while approaching, pushing and running through doors");
  control("max_angular_velocity", &C::max_angular_velocity, "rad/s", Range::positive(),
          "top turn rate there");
  control("track_along_gain", &C::track_along_gain, "1/s", Range::nonNegative(),
          "lane tracking: along-track gain");
  control("track_cross_gain", &C::track_cross_gain, "1/m^2", Range::nonNegative(),
          "cross-track gain (scaled by the reference speed)");
  control("track_heading_gain", &C::track_heading_gain, "1/m", Range::nonNegative(),
          "heading gain (scaled by the reference speed)");
  const auto add = [&table](const std::string& key, double ApproachSettings::*member, const char* unit,
                            Range range, const std::string& meaning) {
    table.add(
        "approach." + key, [member](auto& s) -> auto& { return s.approach.*member; }, unit, range, meaning);
  };
  using A = ApproachSettings;
  add("standoff_m", &A::standoff_m, "m", Range::positive(),
      "the collision-free leg ends this far behind the contact");
  add("standoff_tolerance_m", &A::standoff_tolerance_m, "m", Range::positive(),
      "the stand-off point is reached within this");
  add("heading_tolerance_rad", &A::heading_tolerance_rad, "rad", Range::positive(),
      "... facing the push within this");
  add("creep_speed", &A::creep_speed, "m/s", Range::positive(), "speed over the last stand-off distance");
  add("contact_tolerance_m", &A::contact_tolerance_m, "m", Range::positive(),
      "the contact pose is reached within this");
  add("contact_force_n", &A::contact_force_n, "N", Range::positive(),
      "a bumper force above this means contact ...");
  add("force_contact_reach_m", &A::force_contact_reach_m, "m", Range::nonNegative(),
      "... within this of the contact pose: force felt farther back is not the object (a kerb the lidar "
      "does not show), and standing still there is a contact not reached");
  add("lane_join_m", &A::lane_join_m, "m", Range::nonNegative(),
      "stuck on the way to the stand-off point within this behind the contact, in its lane: creep along it");
  add("lane_join_offset_m", &A::lane_join_offset_m, "m", Range::nonNegative(),
      "... this far beside the lane's line");
  add("lane_join_heading_rad", &A::lane_join_heading_rad, "rad", Range::nonNegative(),
      "... and this far off its heading (0: never)");
  add("align_backup_m", &A::align_backup_m, "m", Range::nonNegative(),
      "the turn to the lane guarded: back up at most this far to free it");
  add("align_turn_margin_m", &A::align_turn_margin_m, "m", Range::nonNegative(),
      "... until it keeps this much more than the guard clearance");
}
void addPushing(Table& table)
{
  const auto pusher = [&table](const std::string& key, double PushTrackerSettings::*member, const char* unit,
                               Range range, const std::string& meaning) {
    table.add(
        "pusher." + key, [member](auto& s) -> auto& { return s.pusher.*member; }, unit, range, meaning);
  };
  using P = PushTrackerSettings;
  pusher("end_tolerance_s", &P::end_tolerance_s, "s", Range::nonNegative(),
         "a push primitive is done this close (in time along its arc) to its end");
  pusher("backoff_m", &P::backoff_m, "m", Range::nonNegative(), "reverse this far before a contact switch");
  pusher("release_m", &P::release_m, "m", Range::nonNegative(), "reverse this far after the last primitive");
  pusher("reverse_speed", &P::reverse_speed, "m/s", Range::positive(), "speed while backing off");
  const auto tactile = [&table](const std::string& key, double TactileSettings::*member, const char* unit,
                                Range range, const std::string& meaning) {
    table.add(
        "tactile." + key, [member](auto& s) -> auto& { return s.tactile.*member; }, unit, range, meaning);
  };
  using T = TactileSettings;
  tactile("max_force_fraction", &T::max_force_fraction, "", Range::interval(0.0, false, 1.0, true),
          "maximum push: this fraction of min(traction limit, force sensor range)");
  tactile("no_motion_time_s", &T::no_motion_time_s, "s", Range::positive(),
          "at maximum push with no motion this long: unpushable");
  tactile("motion_threshold_m", &T::motion_threshold_m, "m", Range::positive(),
          "displacement below this is no motion");
  tactile("min_measured_distance_m", &T::min_measured_distance_m, "m", Range::positive(),
          "push this far before the measured cost is trusted");
  tactile("cost_threshold", &T::cost_threshold, "m", Range::positive(),
          "|J measured - J planned| above this (equivalent metres) updates the affordance");
  tactile("pose_smoothing_s", &T::pose_smoothing_s, "s", Range::nonNegative(),
          "the no-motion window compares the pose averaged over about this long: estimator jitter of "
          "centimetres per sample must not read as motion (0: the raw pose)");
  const auto pushed = [&table](const std::string& key, double PushedObjectSettings::*member, const char* unit,
                               Range range, const std::string& meaning) {
    table.add(
        "pushed_object." + key, [member](auto& s) -> auto& { return s.pushed_object.*member; }, unit, range,
        meaning);
  };
  using O = PushedObjectSettings;
  pushed("radius_m", &O::radius_m, "m", Range::positive(),
         "returns this close to the pushed object's expected centroid path (or its observed centroid) are "
         "its own");
  pushed(
      "guard_clearance_m", &O::guard_clearance_m, "m", Range::nonNegative(),
      "any other return this close to the footprint along the creep/push/back-off command stops the vehicle; "
      "also the least clearance a follower squeezing along a wall keeps");
  pushed("guard_horizon_s", &O::guard_horizon_s, "s", Range::positive(),
         "how far ahead that command is checked");
}

Table makeExecutiveParameters()
{
  Table table(common::Presence::required);
  addTopLevel(table);
  addStallRecovery(table);
  addProgress(table);
  addFollower(table);
  addDoorway(table);
  addControlAndApproach(table);
  addPushing(table);
  return table;
}

}  // namespace

const common::ParameterTable<ExecutiveSettings>& executiveParameters()
{
  static const Table table = makeExecutiveParameters();
  return table;
}

Footprint vehicleFootprint(const common::VehicleSettings& vehicle, double reference_to_bumper_m)
{
  if (!(reference_to_bumper_m > 0.0) || reference_to_bumper_m > vehicle.length_m) {
    throw std::invalid_argument(
        "executive: footprint.reference_to_bumper_m (" + std::to_string(reference_to_bumper_m) +
        ") must be positive and at most the vehicle length (" + std::to_string(vehicle.length_m) + ")");
  }
  Footprint footprint;
  footprint.front_m = reference_to_bumper_m;
  footprint.rear_m = vehicle.length_m - reference_to_bumper_m;
  footprint.half_width_m = vehicle.width_m / 2.0;
  return footprint;
}

ExecutiveSettings loadExecutiveSettings(const common::ConfigNode& node)
{
  ExecutiveSettings settings;
  executiveParameters().read(node, settings);
  if (settings.doorway.min_ahead_m >= settings.doorway.look_ahead_m) {
    node.fail("doorway.min_ahead_m", "must be less than doorway.look_ahead_m");
  }
  // One value, several parts: the follower's target tolerance is the waypoint's, the pusher drives with
  // the approach's control laws, the tactile monitor's contact is the approach's, and a squeezing
  // approach keeps the guard's clearance.
  settings.follower.goal_tolerance_m = settings.waypoint_tolerance_m;
  settings.pusher.control = settings.approach.control;
  settings.tactile.contact_force_n = settings.approach.contact_force_n;
  settings.approach.squeeze_clearance_m = settings.pushed_object.guard_clearance_m;
  // The daemon and the headless runner read this section with loadObstacleSettings, first: it rejects
  // unknown keys of its own section.
  node.acceptAllUnder("obstacles");
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::executive
