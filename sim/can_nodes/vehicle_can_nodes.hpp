#pragma once
// The vehicle's CAN nodes as the simulator plays them: the bumper force sensor (a frame every 10 ms) and
// the two CiA 402 wheel drives (left and right node, DriveEmulator: configured by the motor client over
// SDO, with their own limits and watchdogs), so the frames are exactly what docs/can_frames.md
// specifies. Pure: frames and time in, frames out; no bus, no LCM.

#include <cstdint>
#include <vector>

#include "drivers/can/frame.hpp"
#include "drivers/force_sensor/force_frame.hpp"
#include "sim/can_nodes/drive_emulator.hpp"
#include "sim/physics/physics_world.hpp"
#include "sim/sensing/force_model.hpp"
#include "sim/sensing/sensing_settings.hpp"
#include "sim/sensing/wheel_encoder.hpp"

namespace ifar::sim {

struct CanNodeSettings {
  std::uint8_t left_node_id = 1;
  std::uint8_t right_node_id = 2;
  std::uint32_t force_frame_id = force_sensor::kDefaultFrameId;
  std::int64_t force_period_us = 10'000;  // 100 Hz
  double force_range_n = 800.0;           // vehicle.yaml force_sensor_range_n
  double wheel_radius_m = 0.15;           // vehicle.yaml wheel_radius_m
  WheelModelSettings wheels;              // the drives' encoders (sim.yaml sensing.wheels)
  ForceModelSettings force;               // the force sensor's errors (sim.yaml sensing.force)
  std::uint64_t seed = 1;                 // sim.yaml seed
};

class VehicleCanNodes {
 public:
  explicit VehicleCanNodes(const CanNodeSettings& settings);

  /// A frame received from the bus (NMT, RPDO1 for either drive; others are ignored).
  void onFrame(const can::Frame& frame, std::int64_t now_us);

  /// Advances to `now_us` with the current bumper force and wheel speeds; returns the frames to send
  /// (force frames, heartbeats, TPDO1, EMCY) in order. The force sensor's reading and the drives' actual
  /// velocity (their encoders) pass through the configured sensing models.
  std::vector<can::Frame> update(std::int64_t now_us, double bumper_force_n,
                                 const physics::WheelSpeeds& actual_wheels);

  /// What the drives' power stages are asked for (their velocity demand: zero unless operation is
  /// enabled or a quick stop is ramping down), as wheel rim speeds in m/s.
  physics::WheelSpeeds commandedWheelSpeeds() const;
  /// True when both drives are operation enabled.
  bool drivesEnabled() const;

  DriveEmulator& leftDrive() { return left_; }
  DriveEmulator& rightDrive() { return right_; }
  force_sensor::ForceSensorEmulator& forceSensor() { return force_sensor_; }

 private:
  CanNodeSettings settings_;
  force_sensor::ForceSensorEmulator force_sensor_;
  ForceSensorModel force_model_;
  WheelEncoder left_encoder_;
  WheelEncoder right_encoder_;
  bool force_stuck_ = false;
  DriveEmulator left_;
  DriveEmulator right_;
  std::int64_t next_force_us_ = -1;
};

}  // namespace ifar::sim
