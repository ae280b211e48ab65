// The shipped config/*.yaml load to exactly these settings, section by section: the values every daemon
// and the headless runner run with. Exact comparisons (==, not within a tolerance), so a loader that
// converts a unit or a type differently fails here.

#include <string>

#include <gtest/gtest.h>

#include "system/run_config.hpp"

namespace ifar::runner {
namespace {

const RunRequest& shipped()
{
  static const RunRequest request = loadRunSettings(std::string(IFAR_SOURCE_DIR) + "/config");
  return request;
}

TEST(ShippedConfig, Vehicle)
{
  const common::VehicleSettings& vehicle = shipped().vehicle;
  EXPECT_EQ(vehicle.length_m, 0.9);
  EXPECT_EQ(vehicle.width_m, 0.7);
  EXPECT_EQ(vehicle.wheel_track_m, 0.6);
  EXPECT_EQ(vehicle.wheel_radius_m, 0.15);
  EXPECT_EQ(vehicle.mass_kg, 80.0);
  EXPECT_EQ(vehicle.traction_coefficient, 0.7);
  EXPECT_EQ(vehicle.max_angular_acceleration, 2.0);
  EXPECT_EQ(vehicle.bumper_friction, 0.5);
  EXPECT_EQ(vehicle.lidar_height_m, 0.8);
  EXPECT_EQ(vehicle.lidar_x_m, 0.2);
  EXPECT_EQ(vehicle.force_sensor_range_n, 800.0);
  EXPECT_EQ(shipped().planner.vehicle.width_m, 0.7);
}

TEST(ShippedConfig, PlannerPerceptionAndGraph)
{
  const auto& perception = shipped().planner.perception;
  EXPECT_EQ(perception.layer_size_m, 200.0);
  EXPECT_EQ(perception.cell_size_m, 0.15);
  EXPECT_EQ(perception.inflation_radius_m, 0.35);
  EXPECT_EQ(perception.simplify_epsilon_m, 0.1);
  EXPECT_FALSE(perception.exact_inflation);  // experimental
  EXPECT_EQ(perception.min_polygon_area_m2, 0.05);
  EXPECT_TRUE(perception.remember_background);
  EXPECT_EQ(perception.gap_fill_azimuth_step_deg, 0.0);
  EXPECT_EQ(perception.gap_fill_min_incidence_deg, 3.0);
  EXPECT_EQ(perception.carve_range_m, 20.0);
  EXPECT_EQ(perception.carve_margin_m, 0.1);
  EXPECT_EQ(perception.background_votes, 5);
  const auto& graph = shipped().planner.graph;
  EXPECT_EQ(graph.association_distance_m, 0.5);
  EXPECT_EQ(graph.votes, 10);
  EXPECT_EQ(graph.view_radius_m, 25.0);
  EXPECT_EQ(graph.bucket_size_m, 0.0);
  EXPECT_EQ(graph.route_preference, 0.0);
  EXPECT_EQ(graph.unseen_cost, 0.0);
  EXPECT_EQ(graph.seen_range_m, 15.0);
}

TEST(ShippedConfig, PlannerInteraction)
{
  EXPECT_TRUE(shipped().planner.interaction_enabled);
  const auto& interaction = shipped().planner.interaction;
  EXPECT_EQ(interaction.connectivity.waypoint_offset_m, 1.0);
  EXPECT_EQ(interaction.connectivity.local_layer_size_m, 60.0);
  EXPECT_EQ(interaction.search.heading_bins, 72U);
  EXPECT_EQ(interaction.search.extended_search_radius_m, 8.0);
  EXPECT_EQ(interaction.search.corridor_push_length_m, 60.0);
  EXPECT_EQ(interaction.search.analytic_interval, 4U);
  EXPECT_EQ(interaction.search.max_expansions, 4000U);
  EXPECT_EQ(interaction.search.time_budget_s, 0.05);
  EXPECT_EQ(interaction.search.passage_margin_m, 0.15);
  EXPECT_EQ(interaction.search.unseen_depth_m, 0.5);
  EXPECT_EQ(interaction.loop.default_physics.mass_kg, 20.0);
  EXPECT_EQ(interaction.loop.default_physics.ground_friction, 0.4);
  EXPECT_EQ(interaction.loop.reach_m, 50.0);
  EXPECT_EQ(interaction.loop.track_drop_frames, 5);
  EXPECT_EQ(interaction.loop.outline_memory_restart_m, 0.0);
  EXPECT_EQ(interaction.pusher.max_push_force_n, shipped().vehicle.maxPushForce());
}

TEST(ShippedConfig, PlannerDaemon)
{
  const auto& node = shipped().planner_node;
  EXPECT_EQ(node.rate_hz, 2.5);
  EXPECT_EQ(node.path_resend_hz, 20.0);
  EXPECT_EQ(node.input.stale_input_age_s, 0.5);
  EXPECT_EQ(node.input.max_future_s, 0.5);
  EXPECT_EQ(node.input.pose_history_s, 5.0);
  EXPECT_EQ(node.detector_max_age_s, 1.0);
  EXPECT_EQ(node.arrival_radius_m, 0.5);
  EXPECT_EQ(shipped().planner.arrival_radius_m, 0.5);
  EXPECT_EQ(node.prior_graph, "");
  EXPECT_EQ(node.data_port, 2368);
  EXPECT_EQ(node.vehicle_config, "vehicle.yaml");
  EXPECT_EQ(node.channels.velodyne_packet, "VELODYNE_PACKET");
  EXPECT_EQ(node.channels.blocked_passage, "BLOCKED_PASSAGE");
  EXPECT_EQ(node.channels.planner_status, "PLANNER_STATUS");
}

TEST(ShippedConfig, ExecutiveTopLevel)
{
  const auto& executive = shipped().executive;
  EXPECT_EQ(executive.stale.pose_s, 0.1);
  EXPECT_EQ(executive.stale.path_s, 0.15);
  EXPECT_EQ(executive.stale.obstacles_s, 0.5);
  EXPECT_EQ(executive.stale.odometry_s, 0.1);
  EXPECT_EQ(executive.waypoint_tolerance_m, 0.4);
  EXPECT_EQ(executive.waypoint_pass_radius_m, 1.0);
  EXPECT_EQ(executive.goal_tolerance_m, 0.3);
  EXPECT_EQ(executive.push_switch_radius_m, 1.5);
  EXPECT_EQ(executive.arrived_hold_m, 0.1);
  EXPECT_EQ(executive.blocked_passage_stalls, 3);
  EXPECT_EQ(executive.blocked_passage_on_sight, executive::GapReportScope::NearPushedObjects);
  EXPECT_EQ(executive.pushed_objects_remembered, 8);
  EXPECT_EQ(executive.max_cycle_gap_s, 0.2);
  EXPECT_EQ(executive.reference_to_bumper_m, 0.45);
  EXPECT_EQ(executive.stall_recovery.still_turn_rad, 0.3);
  EXPECT_EQ(executive.stall_recovery.straight_releases, 3.0);
  EXPECT_EQ(executive.stall_recovery.reversing_progress_m, 0.01);
  EXPECT_EQ(executive.stall_recovery.gentle_arc_fraction, 0.5);
}

TEST(ShippedConfig, ExecutiveParts)
{
  const auto& executive = shipped().executive;
  EXPECT_EQ(executive.follower.horizon_s, 2.0);
  EXPECT_EQ(executive.follower.linear_samples, 5);
  EXPECT_EQ(executive.follower.angular_samples, 15);
  EXPECT_EQ(executive.follower.max_linear_velocity, 0.8);
  EXPECT_EQ(executive.follower.navigation_proximity_weight, 3.0);
  EXPECT_EQ(executive.follower.goal_tolerance_m, 0.4);
  EXPECT_TRUE(executive.doorway.enabled);
  EXPECT_EQ(executive.doorway.max_width_m, 1.2);
  EXPECT_EQ(executive.doorway.run_start_tolerance_m, 0.15);
  EXPECT_EQ(executive.doorway.min_crossing_sine, 0.34);
  EXPECT_EQ(executive.approach.control.turn_in_place_error, 0.6);
  EXPECT_EQ(executive.approach.control.track_cross_gain, 8.0);
  EXPECT_EQ(executive.pusher.control.track_heading_gain, 5.0);
  EXPECT_EQ(executive.approach.lane_join_heading_rad, 0.35);
  EXPECT_EQ(executive.approach.align_turn_margin_m, 0.03);
  EXPECT_EQ(executive.approach.squeeze_clearance_m, 0.05);
  EXPECT_EQ(executive.pusher.backoff_m, 0.4);
  EXPECT_EQ(executive.pusher.reverse_speed, 0.2);
  EXPECT_EQ(executive.tactile.max_force_fraction, 0.9);
  EXPECT_EQ(executive.tactile.contact_force_n, 20.0);
  EXPECT_EQ(executive.tactile.min_measured_distance_m, 0.3);
  EXPECT_EQ(executive.tactile.pose_smoothing_s, 0.1);
  EXPECT_EQ(executive.pushed_object.radius_m, 0.8);
  EXPECT_EQ(executive.pushed_object.guard_horizon_s, 0.5);
}

TEST(ShippedConfig, ExecutiveObstacles)
{
  const auto& obstacles = shipped().obstacles;
  EXPECT_EQ(obstacles.packet_channel, "VELODYNE_PACKET");
  EXPECT_EQ(obstacles.max_range_m, 15.0);
  EXPECT_EQ(obstacles.keep_s, 0.15);
  EXPECT_EQ(obstacles.cell_m, 0.05);
}

TEST(ShippedConfig, Simulator)
{
  const auto& sim = shipped().sim;
  EXPECT_EQ(sim.vehicle_config, "vehicle.yaml");
  EXPECT_EQ(sim.world, "");
  EXPECT_EQ(sim.simulator.seed, 1U);
  EXPECT_EQ(sim.simulator.physics.step_seconds, 1.0 / 200.0);
  EXPECT_EQ(sim.simulator.physics.surface_friction, 0.5);
  EXPECT_EQ(sim.simulator.physics.bumper_depth_m, 0.05);
  EXPECT_TRUE(sim.simulator.lidar_enabled);
  EXPECT_EQ(sim.lidar_host, "127.0.0.1");
  EXPECT_EQ(sim.lidar_port, 2368);
  EXPECT_EQ(sim.simulator.lidar_rotation_hz, 10.0);
  EXPECT_EQ(sim.simulator.lidar_max_range_m, 100.0);
  EXPECT_EQ(sim.simulator.lidar_scene.cell_size_m, 2.0);
  EXPECT_EQ(sim.pose_channel, "POSE");
  EXPECT_EQ(sim.pose_rate_hz, 50.0);
  EXPECT_EQ(sim.simulator.sensing.pose.jitter_position_m, 0.0);
  EXPECT_EQ(sim.ground_truth_channel, "SIM_GROUND_TRUTH");
  EXPECT_EQ(sim.ground_truth_rate_hz, 20.0);
  EXPECT_EQ(sim.command_source, sim::CommandSource::kCan);
  EXPECT_EQ(sim.velocity_channel, "VELOCITY_CMD");
  EXPECT_EQ(sim.command_timeout_s, 0.5);
  EXPECT_EQ(sim.can_nodes.left_node_id, 1);
  EXPECT_EQ(sim.can_nodes.right_node_id, 2);
  EXPECT_EQ(sim.can_nodes.force_frame_id, 400U);
}

TEST(ShippedConfig, CanDrivers)
{
  const RunRequest& request = shipped();
  EXPECT_EQ(request.can_channel, "CAN_VEHICLE");
  EXPECT_EQ(request.force_sensor.monitor.frame_id, 400U);
  EXPECT_EQ(request.force_sensor.monitor.silence_timeout_us, 50'000);
  EXPECT_EQ(request.force_sensor.monitor.stuck_counter_frames, 3);
  EXPECT_EQ(request.force_sensor.channel, "FORCE");
  EXPECT_EQ(request.motor.drive.left.node_id, 1);
  EXPECT_EQ(request.motor.drive.right.node_id, 2);
  EXPECT_EQ(request.motor.master_node_id, 127);
  EXPECT_EQ(request.motor.master_heartbeat_period_us, 50'000);
  EXPECT_EQ(request.motor.cycle_us, 10'000);
  EXPECT_EQ(request.motor.drive.left.heartbeat_timeout_us, 300'000);
  EXPECT_EQ(request.motor.drive.right.command_timeout_us, 150'000);
  EXPECT_EQ(request.motor.command_future_tolerance_us, 50'000);
  EXPECT_EQ(request.motor.drive.left.stop_timeout_us, 1'000'000);
  EXPECT_EQ(request.motor.drive.left.sdo_timeout_us, 50'000);
  EXPECT_EQ(request.motor.drive.right.sdo_attempts, 3);
  EXPECT_EQ(request.motor.drive_heartbeat_timeout_ms, 150);
  EXPECT_EQ(request.motor.drive_rpdo_timeout_ms, 100);
  EXPECT_EQ(request.motor.status_channel, "MOTOR_STATUS");
  EXPECT_EQ(request.motor.odometry_channel, "ODOMETRY");
  EXPECT_EQ(request.motor.odometry_timeout_us, 50'000);
  EXPECT_EQ(request.motor.drive.wheel_track_m, 0.6);
}

TEST(ShippedConfig, Velodyne)
{
  const auto& velodyne = shipped().velodyne;
  EXPECT_EQ(velodyne.bind_address, "0.0.0.0");
  EXPECT_EQ(velodyne.data_port, 2368);
  EXPECT_FALSE(velodyne.position_packets);
  EXPECT_EQ(velodyne.position_port, 8308);
  EXPECT_EQ(velodyne.receive_buffer_bytes, 4'194'304);
  EXPECT_EQ(velodyne.data_channel, "VELODYNE_PACKET");
  EXPECT_EQ(velodyne.position_channel, "VELODYNE_POSITION");
  EXPECT_EQ(velodyne.status_channel, "VELODYNE_STATUS");
  EXPECT_EQ(velodyne.status_period_s, 1.0);
  EXPECT_EQ(velodyne.bad_packet_log_interval_s, 1.0);
}

// The lidar point filter, one home (vehicle.yaml lidar:), read by the planner's perception (as the Planner
// completes its settings from its vehicle) and the executive's obstacle points (LocalObstacles takes the
// vehicle) alike.
TEST(ShippedConfig, LidarPointFilter)
{
  const common::LidarFilterSettings& lidar = shipped().vehicle.lidar;
  EXPECT_EQ(lidar.ground_clearance_m, 0.15);
  EXPECT_EQ(lidar.max_height_m, 1.2);
  EXPECT_EQ(lidar.min_range_m, 0.4);
  EXPECT_EQ(lidar.movable_reflectivity_threshold, 101);
  const auto perception =
      perception::withLidarFilter(shipped().planner.perception, shipped().planner.vehicle.lidar);
  EXPECT_EQ(perception.ground_clearance_m, 0.15);
  EXPECT_EQ(perception.vehicle_height_m, 1.2);
  EXPECT_EQ(perception.min_range_m, 0.4);
  EXPECT_EQ(perception.movable_reflectivity_threshold, 101.0F);
}

}  // namespace
}  // namespace ifar::runner
