#include "executive/modes/executive_settings.hpp"

#include <stdexcept>
#include <string>

namespace ifar::executive {
namespace {

double positive(const common::ConfigNode& node, const std::string& key)
{
  const double value = node.required<double>(key);
  if (!(value > 0.0)) {
    node.fail(key, "must be a positive number");
  }
  return value;
}

double nonNegative(const common::ConfigNode& node, const std::string& key)
{
  const double value = node.required<double>(key);
  if (!(value >= 0.0)) {
    node.fail(key, "must be zero or positive");
  }
  return value;
}

int positiveCount(const common::ConfigNode& node, const std::string& key, int minimum)
{
  const int value = node.required<int>(key);
  if (value < minimum) {
    node.fail(key, "must be at least " + std::to_string(minimum));
  }
  return value;
}

GapReportScope gapReportScope(const common::ConfigNode& node, const std::string& key)
{
  const auto value = node.required<std::string>(key);
  if (value == "off") {
    return GapReportScope::Off;
  }
  if (value == "near_pushed_objects") {
    return GapReportScope::NearPushedObjects;
  }
  if (value == "everywhere") {
    return GapReportScope::Everywhere;
  }
  node.fail(key, "must be off, near_pushed_objects or everywhere, not '" + value + "'");
}

PoseControllerSettings loadControl(const common::ConfigNode& node)
{
  PoseControllerSettings control;
  control.linear_gain = positive(node, "linear_gain");
  control.angular_gain = positive(node, "angular_gain");
  control.turn_in_place_error = positive(node, "turn_in_place_error_rad");
  control.max_linear_velocity = positive(node, "max_linear_velocity");
  control.max_angular_velocity = positive(node, "max_angular_velocity");
  control.track_along_gain = nonNegative(node, "track_along_gain");
  control.track_cross_gain = nonNegative(node, "track_cross_gain");
  control.track_heading_gain = nonNegative(node, "track_heading_gain");
  return control;
}

void loadTopLevel(const common::ConfigNode& node, ExecutiveSettings& settings)
{
  settings.stale.pose_s = positive(node, "stale_after_s.pose");
  settings.stale.path_s = positive(node, "stale_after_s.path");
  settings.stale.force_s = positive(node, "stale_after_s.force");
  settings.stale.motor_s = positive(node, "stale_after_s.motor");
  settings.stale.obstacles_s = positive(node, "stale_after_s.obstacles");
  settings.waypoint_tolerance_m = positive(node, "waypoint_tolerance_m");
  settings.waypoint_pass_radius_m = positive(node, "waypoint_pass_radius_m");
  settings.goal_tolerance_m = positive(node, "goal_tolerance_m");
  settings.push_switch_radius_m = positive(node, "push_switch_radius_m");
  settings.arrived_hold_m = nonNegative(node, "arrived_hold_m");
  settings.replan_timeout_s = positive(node, "replan_timeout_s");
  settings.stall_timeout_s = positive(node, "stall_timeout_s");
  settings.blocked_passage_stalls = positiveCount(node, "blocked_passage_stalls", 0);
  settings.stall_site_radius_m = positive(node, "stall_site_radius_m");
  settings.blocked_passage_ahead_m = positive(node, "blocked_passage_ahead_m");
  settings.blocked_passage_on_sight = gapReportScope(node, "blocked_passage_on_sight");
  settings.gap_report_repeat_s = positive(node, "gap_report_repeat_s");
  settings.gap_report_beyond_m = positive(node, "gap_report_beyond_m");
  settings.pushed_objects_remembered = positiveCount(node, "pushed_objects_remembered", 1);
  settings.max_cycle_gap_s = positive(node, "max_cycle_gap_s");
  settings.reference_to_bumper_m = positive(node, "footprint.reference_to_bumper_m");
}

StallRecoverySettings loadStallRecovery(const common::ConfigNode& node)
{
  StallRecoverySettings recovery;
  recovery.still_distance_m = positive(node, "stall_recovery.still_distance_m");
  recovery.still_turn_rad = positive(node, "stall_recovery.still_turn_rad");
  recovery.resume_after_s = positive(node, "stall_recovery.resume_after_s");
  recovery.standstill_timeout_s = positive(node, "stall_recovery.standstill_timeout_s");
  recovery.turn_tolerance_rad = positive(node, "stall_recovery.turn_tolerance_rad");
  recovery.turn_timeout_s = nonNegative(node, "stall_recovery.turn_timeout_s");
  recovery.straight_releases = positive(node, "stall_recovery.straight_releases");
  recovery.reversing_m = nonNegative(node, "stall_recovery.reversing_m");
  recovery.reversing_progress_m = nonNegative(node, "stall_recovery.reversing_progress_m");
  recovery.gentle_arc_fraction = positive(node, "stall_recovery.gentle_arc_fraction");
  if (recovery.gentle_arc_fraction > 1.0) {
    node.fail("stall_recovery.gentle_arc_fraction", "must be at most 1 (a fraction of the turning rate)");
  }
  return recovery;
}

FollowerSettings loadFollower(const common::ConfigNode& node)
{
  FollowerSettings follower;
  follower.horizon_s = positive(node, "follower.horizon_s");
  follower.time_step_s = positive(node, "follower.time_step_s");
  follower.linear_samples = positiveCount(node, "follower.linear_samples", 1);
  follower.angular_samples = positiveCount(node, "follower.angular_samples", 3);
  follower.clearance_m = nonNegative(node, "follower.clearance_m");
  follower.clearance_cap_m = positive(node, "follower.clearance_cap_m");
  follower.progress_weight = nonNegative(node, "follower.progress_weight");
  follower.heading_weight = nonNegative(node, "follower.heading_weight");
  follower.clearance_weight = nonNegative(node, "follower.clearance_weight");
  follower.slow_down_distance_m = nonNegative(node, "follower.slow_down_distance_m");
  follower.max_linear_velocity = positive(node, "follower.max_linear_velocity");
  follower.cell_size_m = positive(node, "follower.cell_size_m");
  follower.navigation_range_m = positive(node, "follower.navigation_range_m");
  follower.navigation_cell_m = positive(node, "follower.navigation_cell_m");
  follower.navigation_proximity_weight = nonNegative(node, "follower.navigation_proximity_weight");
  follower.descent_radius_m = positive(node, "follower.descent_radius_m");
  return follower;
}

DoorwaySettings loadDoorway(const common::ConfigNode& node)
{
  DoorwaySettings doorway;
  doorway.enabled = node.required<bool>("doorway.enabled");
  doorway.max_width_m = positive(node, "doorway.max_width_m");
  doorway.look_ahead_m = positive(node, "doorway.look_ahead_m");
  doorway.min_ahead_m = nonNegative(node, "doorway.min_ahead_m");
  if (doorway.min_ahead_m >= doorway.look_ahead_m) {
    node.fail("doorway.min_ahead_m", "must be less than doorway.look_ahead_m");
  }
  doorway.approach_m = positive(node, "doorway.approach_m");
  doorway.exit_m = positive(node, "doorway.exit_m");
  doorway.max_skew_rad = nonNegative(node, "doorway.max_skew_rad");
  doorway.min_clearance_m = nonNegative(node, "doorway.min_clearance_m");
  doorway.speed = positive(node, "doorway.speed");
  doorway.timeout_s = positive(node, "doorway.timeout_s");
  doorway.retry_after_s = nonNegative(node, "doorway.retry_after_s");
  doorway.retry_radius_m = nonNegative(node, "doorway.retry_radius_m");
  doorway.run_heading_tolerance_rad = positive(node, "doorway.run_heading_tolerance_rad");
  doorway.run_start_tolerance_m = positive(node, "doorway.run_start_tolerance_m");
  doorway.run_end_tolerance_m = positive(node, "doorway.run_end_tolerance_m");
  doorway.passed_margin_m = nonNegative(node, "doorway.passed_margin_m");
  doorway.min_crossing_sine = nonNegative(node, "doorway.min_crossing_sine");
  if (doorway.min_crossing_sine > 1.0) {
    node.fail("doorway.min_crossing_sine", "must be at most 1 (a sine)");
  }
  return doorway;
}

ApproachSettings loadApproach(const common::ConfigNode& node)
{
  ApproachSettings approach;
  approach.standoff_m = positive(node, "approach.standoff_m");
  approach.standoff_tolerance_m = positive(node, "approach.standoff_tolerance_m");
  approach.heading_tolerance_rad = positive(node, "approach.heading_tolerance_rad");
  approach.creep_speed = positive(node, "approach.creep_speed");
  approach.contact_tolerance_m = positive(node, "approach.contact_tolerance_m");
  approach.contact_force_n = positive(node, "approach.contact_force_n");
  approach.lane_join_m = nonNegative(node, "approach.lane_join_m");
  approach.lane_join_offset_m = nonNegative(node, "approach.lane_join_offset_m");
  approach.lane_join_heading_rad = nonNegative(node, "approach.lane_join_heading_rad");
  approach.align_backup_m = nonNegative(node, "approach.align_backup_m");
  approach.align_turn_margin_m = nonNegative(node, "approach.align_turn_margin_m");
  approach.control = loadControl(node.child("control"));
  return approach;
}

TactileSettings loadTactile(const common::ConfigNode& node)
{
  TactileSettings tactile;
  tactile.max_force_fraction = positive(node, "tactile.max_force_fraction");
  if (tactile.max_force_fraction > 1.0) {
    node.fail("tactile.max_force_fraction",
              "must be at most 1 (a fraction of the vehicle's maximum push force)");
  }
  tactile.no_motion_time_s = positive(node, "tactile.no_motion_time_s");
  tactile.motion_threshold_m = positive(node, "tactile.motion_threshold_m");
  tactile.min_measured_distance_m = positive(node, "tactile.min_measured_distance_m");
  tactile.cost_threshold = positive(node, "tactile.cost_threshold");
  return tactile;
}

}  // namespace

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
  loadTopLevel(node, settings);
  settings.stall_recovery = loadStallRecovery(node);
  settings.follower = loadFollower(node);
  settings.follower.goal_tolerance_m = settings.waypoint_tolerance_m;
  settings.doorway = loadDoorway(node);
  settings.approach = loadApproach(node);

  PushTrackerSettings& pusher = settings.pusher;
  pusher.end_tolerance_s = nonNegative(node, "pusher.end_tolerance_s");
  pusher.backoff_m = nonNegative(node, "pusher.backoff_m");
  pusher.release_m = nonNegative(node, "pusher.release_m");
  pusher.reverse_speed = positive(node, "pusher.reverse_speed");
  pusher.control = settings.approach.control;

  settings.tactile = loadTactile(node);
  settings.tactile.contact_force_n = settings.approach.contact_force_n;

  PushedObjectSettings& pushed_object = settings.pushed_object;
  pushed_object.radius_m = positive(node, "pushed_object.radius_m");
  pushed_object.guard_clearance_m = nonNegative(node, "pushed_object.guard_clearance_m");
  pushed_object.guard_horizon_s = positive(node, "pushed_object.guard_horizon_s");
  settings.approach.squeeze_clearance_m = pushed_object.guard_clearance_m;

  // The daemon and the headless runner read this section with loadObstacleSettings, first: it rejects
  // unknown keys of its own section.
  node.acceptAllUnder("obstacles");
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::executive
