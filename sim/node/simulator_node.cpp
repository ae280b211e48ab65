#include "sim/node/simulator_node.hpp"

#include <cmath>
#include <utility>

namespace ifar::sim {
namespace {

CanNodeSettings canNodesFor(const SimNodeSettings& settings, const common::VehicleSettings& vehicle)
{
  CanNodeSettings nodes = settings.can_nodes;
  nodes.force_range_n = vehicle.force_sensor_range_n;
  nodes.wheel_radius_m = vehicle.wheel_radius_m;
  nodes.wheels = settings.simulator.sensing.wheels;
  nodes.force = settings.simulator.sensing.force;
  nodes.seed = settings.simulator.seed;
  return nodes;
}

std::int64_t periodNanoseconds(double rate_hz)
{
  return static_cast<std::int64_t>(1e9 / rate_hz);
}

/// The first multiple of `period_ns` after `time_ns`.
std::int64_t nextDue(std::int64_t time_ns, std::int64_t period_ns)
{
  return time_ns - time_ns % period_ns + period_ns;
}

}  // namespace

ifar::pose_t toPoseMessage(const StepOutput& output)
{
  ifar::pose_t message{};
  message.utime = output.pose_estimate_utime;  // when the estimate is valid, not when it was sent
  const auto& estimate = output.pose_estimate;
  message.position[0] = estimate.pose.x;
  message.position[1] = estimate.pose.y;
  message.position[2] = 0.0;
  message.orientation[0] = std::cos(0.5 * estimate.pose.heading);
  message.orientation[1] = 0.0;
  message.orientation[2] = 0.0;
  message.orientation[3] = std::sin(0.5 * estimate.pose.heading);
  message.velocity[0] = estimate.linear_velocity.x();
  message.velocity[1] = estimate.linear_velocity.y();
  message.velocity[2] = 0.0;
  message.angular_velocity[0] = 0.0;
  message.angular_velocity[1] = 0.0;
  message.angular_velocity[2] = estimate.angular_velocity;
  return message;
}

ifar::world_state_t toGroundTruthMessage(const StepOutput& output)
{
  ifar::world_state_t message{};
  message.utime = output.utime;
  message.vehicle_x = output.vehicle.pose.x;
  message.vehicle_y = output.vehicle.pose.y;
  message.vehicle_heading = output.vehicle.pose.heading;
  message.bumper_force_n = output.bumper_force_n;
  for (const auto& object : output.objects) {
    ifar::object_state_t state{};
    state.id = object.id;
    state.x = object.pose.x;
    state.y = object.pose.y;
    state.heading = object.pose.heading;
    state.linear_velocity[0] = object.linear_velocity.x();
    state.linear_velocity[1] = object.linear_velocity.y();
    state.angular_velocity = object.angular_velocity;
    state.movable = true;
    message.objects.push_back(state);
  }
  message.num_objects = static_cast<std::int32_t>(message.objects.size());
  return message;
}

SimulatorNode::SimulatorNode(World world, const common::VehicleSettings& vehicle,
                             const SimNodeSettings& settings)
    : settings_(settings),
      simulator_(std::move(world), vehicle, settings.simulator),
      nodes_(canNodesFor(settings, vehicle))
{
}

std::int64_t SimulatorNode::nowUtime() const
{
  return settings_.simulator.epoch_utime + simulator_.timeNanoseconds() / 1000;
}

void SimulatorNode::onFrame(const can::Frame& frame, std::int64_t arrival_us)
{
  if (!frame.error()) {
    nodes_.onFrame(frame, arrival_us);
  }
}

void SimulatorNode::onVelocityCommand(const ifar::velocity_cmd_t& command)
{
  last_command_ = command;
}

void SimulatorNode::applyCommand()
{
  if (settings_.command_source == CommandSource::kCan) {
    simulator_.setWheelSpeedCommand(nodes_.commandedWheelSpeeds());
  } else if (last_command_ && nowUtime() - last_command_->utime <
                                  static_cast<std::int64_t>(settings_.command_timeout_s * 1e6)) {
    simulator_.setVelocityCommand(last_command_->linear_velocity, last_command_->angular_velocity);
  } else {
    simulator_.setVelocityCommand(0.0, 0.0);  // no or stale command: stop, as the drives would
  }
}

SimulatorStep SimulatorNode::step(double dt_seconds)
{
  applyCommand();
  SimulatorStep result;
  result.output = simulator_.step(dt_seconds);
  const StepOutput& output = result.output;
  result.frames = nodes_.update(output.utime, output.bumper_force_n, output.wheel_speeds);
  if (output.time_ns >= next_pose_ns_) {
    result.pose = toPoseMessage(output);
    next_pose_ns_ = nextDue(output.time_ns, periodNanoseconds(settings_.pose_rate_hz));
  }
  if (output.time_ns >= next_truth_ns_) {
    result.ground_truth = toGroundTruthMessage(output);
    next_truth_ns_ = nextDue(output.time_ns, periodNanoseconds(settings_.ground_truth_rate_hz));
  }
  return result;
}

}  // namespace ifar::sim
