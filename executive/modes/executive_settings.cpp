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
  settings.stale.pose_s = positive(node, "stale_after_s.pose");
  settings.stale.path_s = positive(node, "stale_after_s.path");
  settings.stale.force_s = positive(node, "stale_after_s.force");
  settings.stale.motor_s = positive(node, "stale_after_s.motor");
  settings.stale.obstacles_s = positive(node, "stale_after_s.obstacles");
  settings.waypoint_tolerance_m = positive(node, "waypoint_tolerance_m");
  settings.waypoint_pass_radius_m = positive(node, "waypoint_pass_radius_m");
  settings.goal_tolerance_m = positive(node, "goal_tolerance_m");
  settings.push_switch_radius_m = positive(node, "push_switch_radius_m");
  settings.replan_timeout_s = positive(node, "replan_timeout_s");
  settings.stall_timeout_s = positive(node, "stall_timeout_s");
  settings.blocked_passage_stalls = positiveCount(node, "blocked_passage_stalls", 0);
  settings.blocked_passage_on_sight = gapReportScope(node, "blocked_passage_on_sight");
  settings.gap_report_repeat_s = positive(node, "gap_report_repeat_s");

  settings.reference_to_bumper_m = positive(node, "footprint.reference_to_bumper_m");

  FollowerSettings& follower = settings.follower;
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
  follower.goal_tolerance_m = settings.waypoint_tolerance_m;

  DoorwaySettings& doorway = settings.doorway;
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

  const common::ConfigNode control = node.child("control");
  ApproachSettings& approach = settings.approach;
  approach.standoff_m = positive(node, "approach.standoff_m");
  approach.standoff_tolerance_m = positive(node, "approach.standoff_tolerance_m");
  approach.heading_tolerance_rad = positive(node, "approach.heading_tolerance_rad");
  approach.creep_speed = positive(node, "approach.creep_speed");
  approach.contact_tolerance_m = positive(node, "approach.contact_tolerance_m");
  approach.contact_force_n = positive(node, "approach.contact_force_n");
  approach.lane_join_m = nonNegative(node, "approach.lane_join_m");
  approach.lane_join_offset_m = nonNegative(node, "approach.lane_join_offset_m");
  approach.lane_join_heading_rad = nonNegative(node, "approach.lane_join_heading_rad");
  approach.control = loadControl(control);

  PushTrackerSettings& pusher = settings.pusher;
  pusher.end_tolerance_s = nonNegative(node, "pusher.end_tolerance_s");
  pusher.backoff_m = nonNegative(node, "pusher.backoff_m");
  pusher.release_m = nonNegative(node, "pusher.release_m");
  pusher.reverse_speed = positive(node, "pusher.reverse_speed");
  pusher.control = approach.control;

  TactileSettings& tactile = settings.tactile;
  tactile.contact_force_n = approach.contact_force_n;
  tactile.max_force_fraction = positive(node, "tactile.max_force_fraction");
  if (tactile.max_force_fraction > 1.0) {
    node.fail("tactile.max_force_fraction",
              "must be at most 1 (a fraction of the vehicle's maximum push force)");
  }
  tactile.no_motion_time_s = positive(node, "tactile.no_motion_time_s");
  tactile.motion_threshold_m = positive(node, "tactile.motion_threshold_m");
  tactile.min_measured_distance_m = positive(node, "tactile.min_measured_distance_m");
  tactile.cost_threshold = positive(node, "tactile.cost_threshold");

  PushedObjectSettings& pushed_object = settings.pushed_object;
  pushed_object.radius_m = positive(node, "pushed_object.radius_m");
  pushed_object.guard_clearance_m = nonNegative(node, "pushed_object.guard_clearance_m");
  pushed_object.guard_horizon_s = positive(node, "pushed_object.guard_horizon_s");
  approach.squeeze_clearance_m = pushed_object.guard_clearance_m;

  // The daemon and the headless runner read this section with loadObstacleSettings, first: it rejects
  // unknown keys of its own section.
  node.acceptAllUnder("obstacles");
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::executive
