#pragma once
// The simulator node's core: the Simulator with the vehicle's CAN nodes (force sensor, two CiA 402
// drives) and the rates at which it reports, without a bus or a clock of its own. Each step applies the
// drives' commanded wheel speeds (or, with `commands: source: lcm`, the last velocity_cmd_t), advances the
// physics, and returns the lidar packets, the CAN nodes' frames, and POSE and SIM_GROUND_TRUTH when due.
// The daemon (sim/daemon) steps it against the wall clock and sends what it returns; the headless runner
// (system/) steps it on simulated time and delivers it to the other nodes' cores.

#include <cstdint>
#include <optional>
#include <vector>

#include "common/vehicle.hpp"
#include "drivers/can/frame.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "ifar/world_state_t.hpp"
#include "sim/can_nodes/vehicle_can_nodes.hpp"
#include "sim/node/node_settings.hpp"
#include "sim/simulator/simulator.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim {

struct SimulatorStep {
  StepOutput output;               // the simulator's own step: packets, ground truth, pose estimate
  std::vector<can::Frame> frames;  // the vehicle's CAN nodes: force frames, heartbeats, TPDO1, EMCY
  std::optional<ifar::pose_t> pose;
  std::optional<ifar::world_state_t> ground_truth;
};

class SimulatorNode {
 public:
  /// The CAN nodes' force range and wheel radius come from `vehicle`. Throws std::invalid_argument naming
  /// the object when the world cannot be simulated.
  SimulatorNode(World world, const common::VehicleSettings& vehicle, const SimNodeSettings& settings);

  /// A frame from the bus (NMT, SDO, RPDO1 and heartbeats for the drives; others are ignored), arriving at
  /// `arrival_us` on the simulated clock (the simulator's own time when it keeps up with the bus).
  void onFrame(const can::Frame& frame, std::int64_t arrival_us);
  void onFrame(const can::Frame& frame) { onFrame(frame, nowUtime()); }
  /// A velocity command (used only with `commands: source: lcm`).
  void onVelocityCommand(const ifar::velocity_cmd_t& command);

  /// Advances by `dt_seconds` (whole physics steps; the remainder carries over).
  SimulatorStep step(double dt_seconds);

  /// The simulator's clock: epoch_utime plus simulated time, microseconds.
  std::int64_t nowUtime() const;
  const Simulator& simulator() const { return simulator_; }
  const VehicleCanNodes& canNodes() const { return nodes_; }

 private:
  void applyCommand();

  SimNodeSettings settings_;
  Simulator simulator_;
  VehicleCanNodes nodes_;
  std::optional<ifar::velocity_cmd_t> last_command_;
  std::int64_t next_pose_ns_ = 0;
  std::int64_t next_truth_ns_ = 0;
};

/// The pose estimate of a step as pose_t (orientation as a unit quaternion about z), stamped with the
/// time the estimate is valid at.
ifar::pose_t toPoseMessage(const StepOutput& output);
/// The ground truth of a step as world_state_t (evaluation only: never read by planner or executive).
ifar::world_state_t toGroundTruthMessage(const StepOutput& output);

}  // namespace ifar::sim
