#include "sensing_run.hpp"

#include "common/vehicle.hpp"
#include "drivers/motor/motor_client.hpp"

namespace ifar::sim::testing {

RunBytes runNode(const World& world, const SimNodeSettings& settings, int steps, double linear,
                 double angular)
{
  const common::VehicleSettings vehicle;
  SimulatorNode node(world, vehicle, settings);
  motor::MotorClientSettings left_settings;
  left_settings.node_id = settings.can_nodes.left_node_id;
  motor::MotorClientSettings right_settings;
  right_settings.node_id = settings.can_nodes.right_node_id;
  motor::MotorClient left(left_settings);
  motor::MotorClient right(right_settings);
  RunBytes run;
  std::vector<can::Frame> to_nodes;
  for (int step = 0; step < steps; ++step) {
    for (const auto& frame : to_nodes) {
      node.onFrame(frame);
    }
    to_nodes.clear();
    SimulatorStep result = node.step(0.005);
    for (const auto& packet : result.output.packets) {
      run.packets.insert(run.packets.end(), packet.begin(), packet.end());
    }
    const std::int64_t now_us = result.output.utime;
    for (const auto& frame : result.frames) {
      for (int byte = 0; byte < 4; ++byte) {
        run.frames.push_back(static_cast<std::uint8_t>(frame.id >> (8 * byte)));
      }
      run.frames.push_back(frame.dlc);
      run.frames.insert(run.frames.end(), frame.data.begin(), frame.data.end());
      left.onFrame(frame, now_us);
      right.onFrame(frame, now_us);
    }
    if (result.pose) {
      std::vector<std::uint8_t> encoded(static_cast<std::size_t>(result.pose->getEncodedSize()));
      result.pose->encode(encoded.data(), 0, static_cast<int>(encoded.size()));
      run.poses.insert(run.poses.end(), encoded.begin(), encoded.end());
      run.pose_messages.push_back(*result.pose);
    }
    run.left_actual.push_back(left.status(now_us).actual_velocity);
    const auto wanted = motor::wheelVelocities(linear, step < steps / 2 ? 0.0 : angular,
                                               vehicle.wheel_track_m, vehicle.wheel_radius_m);
    left.command(wanted.left, now_us);
    right.command(wanted.right, now_us);
    for (auto* client : {&left, &right}) {
      const auto frames = client->update(now_us);
      to_nodes.insert(to_nodes.end(), frames.begin(), frames.end());
    }
    result.output.packets.clear();
    run.outputs.push_back(std::move(result.output));
  }
  return run;
}

std::uint64_t fingerprint(const std::vector<std::uint8_t>& bytes)
{
  std::uint64_t hash = 14695981039346656037ULL;
  for (const std::uint8_t byte : bytes) {
    hash = (hash ^ byte) * 1099511628211ULL;
  }
  return hash;
}

}  // namespace ifar::sim::testing
