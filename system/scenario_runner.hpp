#pragma once
// The headless runner: the simulator and the very cores the daemons wrap (velodyne, force and motor
// drivers, planner, executive), stepped in lock-step in one process on simulated time, exchanging the
// daemons' messages on an in-process bus (simulated_stack.hpp). No clocks, no threads, no LCM:
// deterministic and as fast as the machine allows. Benchmarks and system tests use it; the multi-process
// demo runs the same cores as daemons over LCM. A benchmark row is a statement about what runs on a vehicle.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "common/vehicle.hpp"
#include "drivers/force_sensor/force_sensor_config.hpp"
#include "drivers/motor/motor_config.hpp"
#include "drivers/velodyne/driver_settings.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/obstacles/local_obstacles.hpp"
#include "planner/core/planner.hpp"
#include "planner/node/node_settings.hpp"
#include "sim/node/node_settings.hpp"
#include "sim/world/world.hpp"
#include "system/frame_times.hpp"
#include "system/loss_accounting.hpp"

namespace ifar::runner {

/// A run: the world and goal, and every node's settings as the daemons read them (run_config.hpp loads
/// them from the config files the daemons use).
struct RunRequest {
  sim::World world;  // goal comes separately
  geometry::Point goal = geometry::Point::Zero();
  /// Goals driven in order after `goal` (ifar run --all-goals): each is sent as a new GOAL when the vehicle
  /// arrives at the one before, as an operator or a mission would.
  std::vector<geometry::Point> further_goals;
  common::VehicleSettings vehicle;
  sim::SimNodeSettings sim;                      // sim.yaml: physics, lidar, pose and CAN nodes
  velodyne::DriverSettings velodyne;             // velodyne.yaml
  force_sensor::ForceSensorConfig force_sensor;  // can.yaml force_sensor:
  motor::MotorConfig motor;                      // can.yaml motor:
  std::string can_channel = "CAN_VEHICLE";  // can.yaml bus.lcm_channel: the CAN bus's name in a run's log
  planner::PlannerSettings planner;         // planner.interaction_enabled = false gives FAR mode
  planner::NodeSettings planner_node;       // planner.yaml daemon: rate, path resend, input ages
  executive::ExecutiveSettings executive;
  executive::ObstacleSettings obstacles;
  double max_sim_time_s = 300.0;
  /// The planner knows the world's static obstacles before the run (a map made before; movable objects
  /// are still found by the lidar): what a run costs beyond exploring the unknown.
  bool known_map = false;
  /// When set, every message the nodes exchange is written to this LCM log (ifar replay, lcm-spy).
  std::string log_path;
  /// Split the distance driven beyond the achievable way into RunSummary::losses (loss_accounting.hpp).
  /// Costs a visibility graph of the world at the end of the run.
  bool account_losses = true;
};

/// How long past the tactile monitor's window a push at maximum force may last before its decision
/// counts as missing: the decision has to reach the push sequence and the vehicle has to ease off.
constexpr double kDecisionAllowanceS = 2.0;

/// One goal of a run: from arriving at the goal before (or the start) to arriving at this one.
struct GoalLeg {
  geometry::Point goal = geometry::Point::Zero();
  bool arrived = false;
  double distance_m = 0.0;  // travelled during the leg (ground truth)
  double sim_time_s = 0.0;  // the leg's simulated time
  LossAccount losses;       // the leg's own loss accounting (its goal's achievable way)
};

struct RunSummary {
  bool arrived = false;     // at every goal
  std::string reason;       // why it ended: "arrived", "timeout", "stopped: <executive reason>", ...
  double distance_m = 0.0;  // travelled by the vehicle (ground truth)
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  int pushes = 0;
  int replans = 0;
  int affordance_updates = 0;
  int blocked_passages = 0;  // passages the executive gave up and the planner sealed
  int escalations = 0;       // times the progress monitor dropped what the vehicle was stuck on
  /// Pushes held at the maximum force (true bumper force) longer than the tactile monitor's window plus
  /// kDecisionAllowanceS without an affordance decision; a working monitor keeps this at 0.
  int undecided_saturated_pushes = 0;
  double longest_saturated_push_s = 0.0;    // the longest spell at maximum force without a decision, seconds
  double goal_distance_m = 0.0;             // final ground-truth distance to the goal
  FrameTimes planner_frame;                 // each planner frame: perception, graphs, interaction, search
  FrameTimes interaction;                   // its interaction stage alone (no frame budget in the runner)
  StageFrameTimes stages;                   // the frame's other stages, each alone
  std::vector<geometry::Pose2> trajectory;  // ground truth, one per control cycle
  std::vector<geometry::Pose2> final_objects;  // ground truth object poses at the end, world-file order
  /// Where the distance beyond the achievable way went (valid only when asked for and computable): with
  /// several goals the legs' accounts added up.
  LossAccount losses;
  std::vector<GoalLeg> legs;  // one per goal driven (or reached for), in order
  /// The routes the planner chose one after another and how each ended; pushes and how each ended.
  int routes = 0;
  int routes_switched = 0;  // given up for a cheaper one while they had not got worse
};

/// One planner frame of a run as an observer sees it: the simulated time, the planner after the frame,
/// what the frame gave, the vehicle's ground-truth trajectory so far and the objects' ground-truth states
/// (world-file order). Valid during the call only.
struct FrameView {
  double sim_time_s;
  const planner::Planner& planner;
  const planner::FrameResult& result;
  const std::vector<geometry::Pose2>& trajectory;
  const std::vector<sim::physics::BodyState>& objects;
};
using FrameObserver = std::function<void(const FrameView& frame)>;

/// Deterministic: the same request gives the same summary (except wall_time_s). `progress` (may be empty)
/// is called about once per simulated second with a one-line status. A request that cannot run (goal or
/// rates not finite and positive, a world the simulator refuses, a log that cannot be written) ends at
/// once with arrived false and the reason "bad request: ...". The planner's wall-clock budgets (push
/// search time_budget_s, interaction frame_budget_ms) are lifted for the run (the expansion limit still
/// holds), since a budget in wall time would make the outcome depend on the machine's load: the one way
/// the runner's planner differs from the daemon's. `observe_frame` (may be empty) is called after each
/// planner frame; it cannot change the run.
RunSummary runScenario(const RunRequest& request, const std::function<void(const std::string&)>& progress,
                       const FrameObserver& observe_frame = {});

}  // namespace ifar::runner
