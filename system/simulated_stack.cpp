#include "system/simulated_stack.hpp"

#include <cmath>
#include <utility>

#include <spdlog/sinks/null_sink.h>

#include "common/span.hpp"

namespace ifar::runner {
namespace {

// Who is on the vehicle's CAN bus.
constexpr CanParticipant kSimulatorOnCan = 1;
constexpr CanParticipant kMotorDriverOnCan = 2;
constexpr CanParticipant kForceDriverOnCan = 3;
// The motor driver reports its drives this often.
constexpr double kMotorStatusPeriodS = 0.1;
// Stand in for the planner's wall-clock budgets (per push search, per frame of interaction planning),
// which a deterministic run cannot use: the expansion limit still bounds each search.
constexpr double kUnlimitedSearchBudgetS = 1e9;
constexpr double kUnlimitedFrameBudgetMs = 1e12;

planner::Planner makePlanner(const RunRequest& request)
{
  planner::Planner planner(runnerPlannerSettings(request));
  if (request.known_map) {
    std::vector<geometry::Polygon> outlines;
    outlines.reserve(request.world.obstacles.size());
    for (const sim::StaticObstacle& obstacle : request.world.obstacles) {
      outlines.push_back(obstacle.outline);
    }
    planner.rememberKnownObstacles(common::Span<const geometry::Polygon>(outlines.data(), outlines.size()));
  }
  return planner;
}

std::shared_ptr<spdlog::logger> silentLogger()
{
  return std::make_shared<spdlog::logger>("runner", std::make_shared<spdlog::sinks::null_sink_mt>());
}

}  // namespace

planner::PlannerSettings runnerPlannerSettings(const RunRequest& request)
{
  planner::PlannerSettings settings = request.planner;
  settings.vehicle = request.vehicle;
  settings.interaction.search.time_budget_s = kUnlimitedSearchBudgetS;
  settings.interaction.loop.frame_budget_ms = kUnlimitedFrameBudgetMs;
  return settings;
}

SimulatedStack::SimulatedStack(const RunRequest& request, StackObservers observers)
    : observers_(std::move(observers)),
      logger_(silentLogger()),
      bus_(request.can_channel),
      simulator_(request.world, request.vehicle, request.sim),
      lidar_port_(request.sim.lidar_port),
      pose_channel_(request.sim.pose_channel),
      ground_truth_channel_(request.sim.ground_truth_channel),
      step_seconds_(request.sim.simulator.physics.step_seconds),
      velodyne_(request.velodyne, logger_),
      force_(request.force_sensor.monitor, logger_),
      motor_(request.motor, request.vehicle),
      force_channel_(request.force_sensor.channel),
      motor_status_channel_(request.motor.status_channel),
      motor_odometry_channel_(request.motor.odometry_channel),
      planner_node_(request.planner_node, logger_, simulator_.nowUtime()),
      planner_(makePlanner(request)),
      planner_channels_(request.planner_node.channels),
      executive_(request.executive, request.obstacles, request.vehicle, logger_)
{
  subscribeNodes(request);
  addTimers(request);
  sendGoal(request.goal, kFirstGoalId);
}

void SimulatedStack::sendGoal(const geometry::Point& goal, std::int64_t goal_id)
{
  ifar::goal_t message{};
  message.utime = simulator_.nowUtime();
  message.goal_id = goal_id;
  message.x = goal.x();
  message.y = goal.y();
  bus_.publish(planner_channels_.goal, message);
}

SimulatedStack::~SimulatedStack() = default;

void SimulatedStack::subscribeNodes(const RunRequest& request)
{
  const planner::PlannerChannels& channels = planner_channels_;
  bus_.subscribeFrames(kSimulatorOnCan,
                       [this](const can::Frame& frame, std::int64_t) { simulator_.onFrame(frame); });
  bus_.subscribeFrames(kMotorDriverOnCan, [this](const can::Frame& frame, std::int64_t now_us) {
    motor_.onFrame(frame, now_us);
  });
  bus_.subscribeFrames(kForceDriverOnCan, [this](const can::Frame& received, std::int64_t now_us) {
    can::Frame frame = received;
    frame.timestamp_us = now_us;  // as the force driver stamps frames from a bus without kernel time
    if (const auto force = force_.onFrame(frame, now_us)) {
      bus_.publish(force_channel_, *force);
    }
  });
  if (request.sim.command_source == sim::CommandSource::kLcm) {
    bus_.subscribe<ifar::velocity_cmd_t>(
        request.sim.velocity_channel,
        [this](const ifar::velocity_cmd_t& message, std::int64_t) { simulator_.onVelocityCommand(message); });
  }
  bus_.subscribe<ifar::velocity_cmd_t>(executive::kCommandChannel,
                                       [this](const ifar::velocity_cmd_t& message, std::int64_t now_us) {
                                         motor_.onVelocityCommand(message, now_us);
                                       });
  bus_.subscribe<ifar::velodyne_packet_t>(
      channels.velodyne_packet, [this](const ifar::velodyne_packet_t& message, std::int64_t now_us) {
        planner_node_.onVelodynePacket(message, now_us);
      });
  bus_.subscribe<ifar::pose_t>(channels.pose, [this](const ifar::pose_t& message, std::int64_t now_us) {
    planner_node_.onPose(message, now_us);
  });
  bus_.subscribe<ifar::goal_t>(channels.goal, [this](const ifar::goal_t& message, std::int64_t now_us) {
    if (planner_node_.onGoal(message, now_us)) {
      runPlannerJob(planner_node_.takeUpdateJob(false), now_us);
    }
  });
  bus_.subscribe<ifar::affordance_t>(channels.affordance,
                                     [this](const ifar::affordance_t& message, std::int64_t now_us) {
                                       planner_node_.onAffordance(message, now_us);
                                       runPlannerJob(planner_node_.takeUpdateJob(false), now_us);
                                     });
  bus_.subscribe<ifar::blocked_passage_t>(
      channels.blocked_passage, [this](const ifar::blocked_passage_t& message, std::int64_t now_us) {
        planner_node_.onBlockedPassage(message, now_us);
        runPlannerJob(planner_node_.takeUpdateJob(false), now_us);
      });
  bus_.subscribe<ifar::pose_t>(
      executive::kPoseChannel,
      [this](const ifar::pose_t& message, std::int64_t now_us) { executive_.onPose(message, now_us); });
  bus_.subscribe<ifar::velodyne_packet_t>(
      request.obstacles.packet_channel, [this](const ifar::velodyne_packet_t& message, std::int64_t now_us) {
        executive_.onVelodynePacket(message, now_us);
      });
  bus_.subscribe<ifar::path_t>(
      executive::kPathChannel,
      [this](const ifar::path_t& message, std::int64_t now_us) { executive_.onPath(message, now_us); });
  bus_.subscribe<ifar::force_t>(
      executive::kForceChannel,
      [this](const ifar::force_t& message, std::int64_t now_us) { executive_.onForce(message, now_us); });
  bus_.subscribe<ifar::motor_status_t>(executive::kMotorStatusChannel,
                                       [this](const ifar::motor_status_t& message, std::int64_t now_us) {
                                         executive_.onMotorStatus(message, now_us);
                                       });
  bus_.subscribe<ifar::odometry_t>(executive::kOdometryChannel,
                                   [this](const ifar::odometry_t& message, std::int64_t now_us) {
                                     executive_.onOdometry(message, now_us);
                                   });
  bus_.subscribe<ifar::e_stop_t>(
      executive::kEStopChannel,
      [this](const ifar::e_stop_t& message, std::int64_t now_us) { executive_.onEStop(message, now_us); });
}

void SimulatedStack::every(double period_s, std::function<void(std::int64_t now_us)> fire)
{
  const auto period_us = std::max<std::int64_t>(1, std::llround(period_s * 1e6));
  timers_.push_back(Timer{period_us, simulator_.nowUtime() + period_us, std::move(fire)});
}

void SimulatedStack::addTimers(const RunRequest& request)
{
  every(static_cast<double>(request.motor.cycle_us) * 1e-6, [this](std::int64_t now_us) {
    for (const can::Frame& frame : motor_.cycle(now_us)) {
      bus_.publishFrame(kMotorDriverOnCan, frame);
    }
    bus_.publish(motor_odometry_channel_, motor_.odometry(now_us));
  });
  every(kMotorStatusPeriodS, [this](std::int64_t now_us) {
    for (const ifar::motor_status_t& status : motor_.statusMessages(now_us)) {
      bus_.publish(motor_status_channel_, status);
    }
  });
  every(request.sim.simulator.physics.step_seconds, [this](std::int64_t now_us) {
    if (const auto silent = force_.silenceReport(now_us)) {
      bus_.publish(force_channel_, *silent);
    }
  });
  every(1.0 / request.planner_node.rate_hz, [this](std::int64_t now_us) {
    planner::PlannerTick tick = planner_node_.tick(now_us, false);
    if (tick.waiting_status) {
      bus_.publish(planner_channels_.planner_status, *tick.waiting_status);
    }
    runPlannerJob(std::move(tick.job), now_us);
  });
  every(1.0 / request.planner_node.path_resend_hz, [this](std::int64_t now_us) {
    if (const std::optional<ifar::path_t> path = planner_node_.resendPath(now_us)) {
      bus_.publish(planner_channels_.global_path, *path);
    }
  });
  every(executive::kControlPeriodS, [this](std::int64_t now_us) {
    const executive::ExecutiveOutputs outputs = executive_.cycle(now_us);
    publishExecutive(outputs);
    if (observers_.executive_cycled) {
      observers_.executive_cycled(outputs, now_us);
    }
  });
}

void SimulatedStack::runPlannerJob(std::optional<planner::PlannerJob> job, std::int64_t now_us)
{
  if (!job) {
    return;
  }
  const planner::PlannerJobResult finished = planner::runPlannerJob(planner_, *job);
  if (observers_.planner_finished) {
    observers_.planner_finished(*job, finished, now_us);
  }
  planner::PlannerOutputs outputs = planner::toOutputs(planner_, finished, now_us, false);
  planner_node_.finish(outputs);
  bus_.publish(planner_channels_.global_path, std::move(outputs.path));
  bus_.publish(planner_channels_.planner_status, std::move(outputs.status));
}

void SimulatedStack::publishExecutive(const executive::ExecutiveOutputs& outputs)
{
  bus_.publish(executive::kCommandChannel, outputs.command);
  if (outputs.status) {
    bus_.publish(executive::kStatusChannel, *outputs.status);
  }
  if (outputs.affordance) {
    bus_.publish(executive::kAffordanceChannel, *outputs.affordance);
  }
  if (outputs.blocked_passage) {
    bus_.publish(executive::kBlockedPassageChannel, *outputs.blocked_passage);
  }
}

const sim::SimulatorStep& SimulatedStack::step()
{
  bus_.deliverFramesTo(kSimulatorOnCan, simulator_.nowUtime());
  last_step_ = simulator_.step(step_seconds_);
  const std::int64_t now_us = simulator_.nowUtime();
  if (observers_.simulator_stepped) {
    observers_.simulator_stepped(last_step_);
  }
  for (const auto& packet : last_step_.output.packets) {
    const common::ByteView payload(packet.data(), packet.size());
    if (auto forwarded = velodyne_.onDatagram(lidar_port_, payload, now_us)) {
      bus_.publish(std::move(forwarded->channel), std::move(forwarded->packet));
    }
  }
  for (const can::Frame& frame : last_step_.frames) {
    bus_.publishFrame(kSimulatorOnCan, frame);
  }
  if (last_step_.pose) {
    bus_.publish(pose_channel_, *last_step_.pose);
  }
  if (last_step_.ground_truth) {
    bus_.publish(ground_truth_channel_, *last_step_.ground_truth);
  }
  bus_.deliver(now_us);
  for (Timer& timer : timers_) {
    if (now_us >= timer.next_due_us) {
      timer.next_due_us += timer.period_us * (1 + (now_us - timer.next_due_us) / timer.period_us);
      timer.fire(now_us);
    }
  }
  return last_step_;
}

}  // namespace ifar::runner
