#include "sim/can_nodes/vehicle_can_nodes.hpp"

#include <gtest/gtest.h>

#include "drivers/force_sensor/force_frame.hpp"
#include "drivers/motor/motor_client.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::sim {
namespace {

TEST(VehicleCanNodes, SendsForceFramesAt100HzThatDecodeToTheBumperForce)
{
  VehicleCanNodes nodes(CanNodeSettings{});
  std::vector<force_sensor::ForceReading> readings;
  for (std::int64_t now_us = 0; now_us < 100'000; now_us += 5'000) {
    for (const auto& frame : nodes.update(now_us, 123.456, {})) {
      const auto decoded = force_sensor::decodeForceFrame(frame);
      if (decoded.status == force_sensor::DecodeStatus::kOk) {
        readings.push_back(decoded.reading);
      }
    }
  }
  ASSERT_EQ(readings.size(), 10u);
  EXPECT_NEAR(readings[0].force_newtons, 123.456, 0.0005);
  EXPECT_EQ(readings[1].counter, static_cast<std::uint8_t>(readings[0].counter + 1));
  EXPECT_FALSE(readings[0].overload);
  // Above the sensor's range: saturated and flagged.
  for (const auto& frame : nodes.update(100'000, 2000.0, {})) {
    const auto decoded = force_sensor::decodeForceFrame(frame);
    if (decoded.status == force_sensor::DecodeStatus::kOk) {
      EXPECT_TRUE(decoded.reading.overload);
      EXPECT_NEAR(decoded.reading.force_newtons, 800.0, 0.001);
    }
  }
}

TEST(VehicleCanNodes, MotorClientsEnableTheDrivesAndCommandWheelSpeeds)
{
  VehicleCanNodes nodes(CanNodeSettings{});
  motor::MotorClientSettings left_settings;
  left_settings.node_id = 1;
  motor::MotorClientSettings right_settings;
  right_settings.node_id = 2;
  motor::MotorClient left(left_settings);
  motor::MotorClient right(right_settings);
  // 0.3 m/s forward, 0.5 rad/s: rims at 0.3 -+ 0.15 m/s.
  const auto wanted = motor::wheelVelocities(0.3, 0.5, 0.6, 0.15);
  std::vector<can::Frame> to_nodes;
  physics::WheelSpeeds actual;
  for (std::int64_t now_us = 0; now_us < 1'500'000; now_us += 10'000) {
    for (const auto& frame : to_nodes) {
      nodes.onFrame(frame, now_us);
    }
    to_nodes.clear();
    for (const auto& frame : nodes.update(now_us, 0.0, actual)) {
      left.onFrame(frame, now_us);
      right.onFrame(frame, now_us);
    }
    left.command(wanted.left, now_us);
    right.command(wanted.right, now_us);
    for (auto* client : {&left, &right}) {
      const auto frames = client->update(now_us);
      to_nodes.insert(to_nodes.end(), frames.begin(), frames.end());
    }
    actual = nodes.commandedWheelSpeeds();  // an ideal wheel
  }
  EXPECT_TRUE(nodes.drivesEnabled());
  EXPECT_NEAR(nodes.commandedWheelSpeeds().left, 0.15, 1e-3);
  EXPECT_NEAR(nodes.commandedWheelSpeeds().right, 0.45, 1e-3);
  EXPECT_EQ(left.status(1'500'000).actual_velocity, wanted.left);
}

TEST(VehicleCanNodes, DrivesCommandedOverCanPushTheSimulatedVehicleIntoAHeavyBox)
{
  // The daemon's wiring in lock-step: client frames -> nodes -> physics -> nodes -> force frames.
  const common::VehicleSettings vehicle;
  SimulatorSettings settings;
  settings.lidar_enabled = false;
  Simulator simulator(builtinPushRoom(200.0), vehicle, settings);
  CanNodeSettings node_settings;
  node_settings.force_range_n = vehicle.force_sensor_range_n;
  node_settings.wheel_radius_m = vehicle.wheel_radius_m;
  VehicleCanNodes nodes(node_settings);
  motor::MotorClientSettings left_settings;
  left_settings.node_id = 1;
  motor::MotorClientSettings right_settings;
  right_settings.node_id = 2;
  motor::MotorClient left(left_settings);
  motor::MotorClient right(right_settings);
  const auto wanted = motor::wheelVelocities(0.5, 0.0, vehicle.wheel_track_m, vehicle.wheel_radius_m);
  std::vector<can::Frame> to_nodes;
  double last_force = -1.0;
  StepOutput output;
  for (int cycle = 0; cycle < 600; ++cycle) {
    const std::int64_t now_us = settings.epoch_utime + simulator.timeNanoseconds() / 1000;
    for (const auto& frame : to_nodes) {
      nodes.onFrame(frame, now_us);
    }
    to_nodes.clear();
    simulator.setWheelSpeedCommand(nodes.commandedWheelSpeeds());
    output = simulator.step(0.01);
    for (const auto& frame : nodes.update(output.utime, output.bumper_force_n, output.wheel_speeds)) {
      const auto force = force_sensor::decodeForceFrame(frame);
      if (force.status == force_sensor::DecodeStatus::kOk) {
        last_force = force.reading.force_newtons;
      }
      left.onFrame(frame, output.utime);
      right.onFrame(frame, output.utime);
    }
    left.command(wanted.left, output.utime);
    right.command(wanted.right, output.utime);
    for (auto* client : {&left, &right}) {
      const auto frames = client->update(output.utime);
      to_nodes.insert(to_nodes.end(), frames.begin(), frames.end());
    }
  }
  EXPECT_TRUE(nodes.drivesEnabled());
  // Stalled at the box (start x 2, box face at 3.2, bumper 0.45 ahead of the axle).
  EXPECT_NEAR(output.vehicle.pose.x, 3.2 - 0.45, 0.02);
  EXPECT_NEAR(last_force, vehicle.maxPushForce(), 0.05 * vehicle.maxPushForce());
  // The wheels spin at the command while the vehicle stands: what TPDO1 reports.
  EXPECT_EQ(left.status(output.utime).actual_velocity, wanted.left);
}

}  // namespace
}  // namespace ifar::sim
