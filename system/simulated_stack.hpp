#pragma once
// The whole stack in one process: the simulator node and the node cores of the velodyne, force and motor
// drivers, the planner and the executive, on a SimulatedBus with the channels and timer periods the
// daemons use. Each step():
//   1. the CAN frames sent since the last step reach the simulator (its drives act on them),
//   2. the simulator advances one physics step; its lidar packets go to the velodyne driver's core as UDP
//      datagrams would, its POSE, SIM_GROUND_TRUTH and CAN frames onto the bus,
//   3. everything published is delivered, stamped with the new time (messages first, as a daemon's loop
//      handles what arrived before its timers),
//   4. the nodes' timers that are due run (motor cycle with its ODOMETRY, motor status, force silence
//      check, planner tick and path resend, executive control cycle); what they publish is delivered at
//      the next step.
// The planner's jobs run in line at once. Nothing here is glue of its own: every conversion and rule is
// in the node cores the daemons wrap.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "drivers/force_sensor/force_driver_node.hpp"
#include "drivers/motor/motor_driver_node.hpp"
#include "drivers/velodyne/packet_forwarder.hpp"
#include "executive/node/executive_node.hpp"
#include "planner/core/planner.hpp"
#include "planner/node/planner_node.hpp"
#include "sim/node/simulator_node.hpp"
#include "system/scenario_runner.hpp"
#include "system/simulated_bus.hpp"

namespace ifar::runner {

/// What the stack tells the one running it (all optional).
struct StackObservers {
  /// The simulator stepped (before what it sent is delivered and before the timers run).
  std::function<void(const sim::SimulatorStep& step)> simulator_stepped;
  /// A planner job finished at `now_us` (with a frame or a replan), before its outputs are published.
  std::function<void(const planner::PlannerJob& job, const planner::PlannerJobResult& finished,
                     std::int64_t now_us)>
      planner_finished;
  /// An executive control cycle ran at `now_us`.
  std::function<void(const executive::ExecutiveOutputs& outputs, std::int64_t now_us)> executive_cycled;
};

/// The planner's settings in a run: the request's, with the vehicle, and with the wall-clock budgets lifted
/// (a deterministic run cannot depend on the machine's load; the expansion limit still bounds a search).
planner::PlannerSettings runnerPlannerSettings(const RunRequest& request);

class SimulatedStack {
 public:
  /// Publishes the goal (delivered with the first step). Throws std::invalid_argument when the simulator
  /// or the executive refuses the world or the vehicle.
  SimulatedStack(const RunRequest& request, StackObservers observers);
  SimulatedStack(const SimulatedStack&) = delete;
  SimulatedStack& operator=(const SimulatedStack&) = delete;
  ~SimulatedStack();

  /// Records every message delivered from now on to an LCM log; the reason when it cannot.
  std::string recordTo(const std::string& path) { return bus_.recordTo(path); }

  /// One physics step (see above); the simulator's step output.
  const sim::SimulatorStep& step();
  /// Delivers what the last step's timers published (at the end of a run, so its log holds every message).
  void flush() { bus_.deliver(nowUtime()); }
  /// Publishes a new goal (delivered with the next step), as an operator's GOAL would arrive.
  void sendGoal(const geometry::Point& goal, std::int64_t goal_id);
  /// The id of the goal the constructor published.
  static constexpr std::int64_t kFirstGoalId = 1;

  std::int64_t nowUtime() const { return simulator_.nowUtime(); }
  const planner::Planner& planner() const { return planner_; }
  const sim::SimulatorNode& simulator() const { return simulator_; }
  const std::string& recordingError() const { return bus_.recordingError(); }

 private:
  struct Timer {
    std::int64_t period_us;
    std::int64_t next_due_us;
    std::function<void(std::int64_t now_us)> fire;
  };
  void subscribeNodes(const RunRequest& request);
  void addTimers(const RunRequest& request);
  void every(double period_s, std::function<void(std::int64_t now_us)> fire);
  void runPlannerJob(std::optional<planner::PlannerJob> job, std::int64_t now_us);
  void publishExecutive(const executive::ExecutiveOutputs& outputs);

  StackObservers observers_;
  std::shared_ptr<spdlog::logger> logger_;  // the nodes' warnings go nowhere: the summary says what matters
  SimulatedBus bus_;
  sim::SimulatorNode simulator_;
  std::uint16_t lidar_port_;
  std::string pose_channel_;
  std::string ground_truth_channel_;
  double step_seconds_;
  velodyne::PacketForwarder velodyne_;
  force_sensor::ForceDriverNode force_;
  motor::MotorDriverNode motor_;
  std::string force_channel_;
  std::string motor_status_channel_;
  std::string motor_odometry_channel_;
  planner::PlannerNode planner_node_;
  planner::Planner planner_;
  planner::PlannerChannels planner_channels_;
  executive::ExecutiveNode executive_;
  sim::SimulatorStep last_step_;
  std::vector<Timer> timers_;
};

}  // namespace ifar::runner
