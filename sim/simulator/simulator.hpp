#pragma once
// The stepping API: commands in, step(dt), sensor data out. No LCM and no CAN: the daemon and the
// headless runner wrap it. Deterministic: the same world, settings, seed and command sequence give the
// same trajectory, packets and readings bit for bit.

#include <cstdint>
#include <memory>
#include <vector>

#include "common/vehicle.hpp"
#include "sim/lidar/lidar_scene.hpp"
#include "sim/lidar/vlp16_scanner.hpp"
#include "sim/physics/physics_world.hpp"
#include "sim/sensing/pose_model.hpp"
#include "sim/sensing/sensing_settings.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim {

struct SimulatorSettings {
  physics::PhysicsSettings physics;
  lidar::LidarSceneSettings lidar_scene;
  double lidar_rotation_hz = 10.0;
  double lidar_max_range_m = 100.0;
  bool lidar_enabled = true;
  /// What the sensors make of the truth (pose estimate, lidar returns, wheel slip and encoders, force
  /// sensor); the default is the ideal profile: every sensor exact.
  SensingSettings sensing;
  std::uint64_t seed = 1;  // every sensing model draws from it
  /// Unix time in microseconds of simulation time 0 (packet timestamps, message times).
  std::int64_t epoch_utime = 1'700'000'000'000'000;
};

struct StepOutput {
  std::int64_t time_ns = 0;                 // simulation time at the end of the step
  std::int64_t utime = 0;                   // epoch_utime + time
  std::vector<lidar::Vlp16Packet> packets;  // completed during the step, in order
  double bumper_force_n = 0.0;              // mean normal bumper force over the step's physics steps
  physics::BodyState pose_estimate;         // what the state estimator publishes (sensing.pose)
  std::int64_t pose_estimate_utime = 0;     // the time the estimate is valid at (utime less the latency)
  physics::BodyState vehicle;               // ground truth
  std::vector<physics::BodyState> objects;  // ground truth, world-file order
  physics::WheelSpeeds wheel_speeds;        // what the wheel encoders report
};

class Simulator {
 public:
  /// Throws std::invalid_argument naming the object when the world cannot be simulated.
  Simulator(World world, const common::VehicleSettings& vehicle, const SimulatorSettings& settings);

  void setVelocityCommand(double linear, double angular) { physics_.setVelocityCommand(linear, angular); }
  void setWheelSpeedCommand(const physics::WheelSpeeds& wheels) { physics_.setWheelSpeedCommand(wheels); }

  /// Advances by `dt_seconds` in whole physics steps; a remainder shorter than one step is carried over
  /// to the next call, so any dt sequence keeps simulation time exact.
  StepOutput step(double dt_seconds);

  std::int64_t timeNanoseconds() const { return time_ns_; }
  const World& world() const { return world_; }
  const physics::PhysicsWorld& physics() const { return physics_; }
  const lidar::LidarScene& lidarScene() const { return scene_; }
  /// The state estimator's model: its drift and corrections so far (tests, tools).
  const PoseEstimateModel& poseModel() const { return pose_model_; }
  /// Every laser fired since the last call is kept here when recording is on (tests, tools).
  void recordReturns(bool enabled) { record_returns_ = enabled; }
  std::vector<lidar::Vlp16Return> takeReturns();

 private:
  std::vector<lidar::Prism> movablePrisms() const;
  void observeTruth();

  World world_;
  SimulatorSettings settings_;
  physics::PhysicsWorld physics_;
  lidar::LidarScene scene_;
  lidar::Vlp16Scanner scanner_;
  std::int64_t step_ns_ = 0;
  std::int64_t time_ns_ = 0;
  std::int64_t carried_ns_ = 0;
  PoseEstimateModel pose_model_;
  bool record_returns_ = false;
  std::vector<lidar::Vlp16Return> returns_;
};

}  // namespace ifar::sim
