#include "sim/simulator/simulator.hpp"

#include <cmath>
#include <stdexcept>

#include "sim/world/world_geometry.hpp"

namespace ifar::sim {
namespace {

lidar::Vlp16Settings scannerSettings(const common::VehicleSettings& vehicle,
                                     const SimulatorSettings& settings)
{
  lidar::Vlp16Settings scanner;
  scanner.rotation_hz = settings.lidar_rotation_hz;
  scanner.max_range_m = settings.lidar_max_range_m;
  scanner.mount_x_m = vehicle.lidar_x_m;
  scanner.mount_height_m = vehicle.lidar_height_m;
  scanner.model = settings.sensing.lidar;
  scanner.seed = settings.seed;
  return scanner;
}

physics::PhysicsSettings physicsSettings(const SimulatorSettings& settings)
{
  physics::PhysicsSettings physics = settings.physics;
  physics.slip_ratio_scale = settings.sensing.wheels.slip_ratio_scale;
  return physics;
}

}  // namespace

Simulator::Simulator(World world, const common::VehicleSettings& vehicle, const SimulatorSettings& settings)
    : world_(std::move(world)),
      settings_(settings),
      physics_(world_, vehicle, physicsSettings(settings)),
      scene_(lidar::LidarScene::fromWorld(world_, settings.lidar_scene)),
      scanner_(scannerSettings(vehicle, settings)),
      step_ns_(std::llround(settings.physics.step_seconds * 1e9)),
      pose_model_(settings.sensing.pose, settings.seed)
{
  if (step_ns_ <= 0) {
    throw std::invalid_argument("simulator settings: physics step must be at least 1 ns");
  }
  scene_.setMovables(movablePrisms());
  observeTruth();
}

void Simulator::observeTruth()
{
  const physics::BodyState truth = physics_.vehicleState();
  pose_model_.advance({time_ns_, truth.pose, truth.linear_velocity, truth.angular_velocity});
}

std::vector<lidar::Prism> Simulator::movablePrisms() const
{
  std::vector<lidar::Prism> prisms;
  const auto states = physics_.objectStates();
  prisms.reserve(states.size());
  for (std::size_t index = 0; index < states.size() && index < world_.objects.size(); ++index) {
    const auto& object = world_.objects[index];
    lidar::Prism prism;
    prism.height_m = object.height_m;
    prism.reflectivity = object.reflectivity;
    prism.outline = placedOutline(object, states[index].pose);
    prisms.push_back(std::move(prism));
  }
  return prisms;
}

StepOutput Simulator::step(double dt_seconds)
{
  StepOutput output;
  if (std::isfinite(dt_seconds) && dt_seconds > 0.0) {
    carried_ns_ += std::llround(dt_seconds * 1e9);
  }
  double force_sum = 0.0;
  int steps = 0;
  while (carried_ns_ >= step_ns_) {
    carried_ns_ -= step_ns_;
    const geometry::Pose2 before = physics_.vehicleState().pose;
    physics_.step();
    time_ns_ += step_ns_;
    observeTruth();
    force_sum += physics_.bumperForce();
    ++steps;
    if (settings_.lidar_enabled) {
      if (!world_.objects.empty()) {
        scene_.setMovables(movablePrisms());
      }
      auto packets = scanner_.advance(time_ns_, before, physics_.vehicleState().pose, scene_,
                                      settings_.epoch_utime, record_returns_ ? &returns_ : nullptr);
      output.packets.insert(output.packets.end(), packets.begin(), packets.end());
    }
  }
  output.time_ns = time_ns_;
  output.utime = settings_.epoch_utime + time_ns_ / 1000;
  output.bumper_force_n = steps > 0 ? force_sum / steps : physics_.bumperForce();
  output.vehicle = physics_.vehicleState();
  output.objects = physics_.objectStates();
  output.wheel_speeds = physics_.wheelSpeeds();
  const VehicleMotion estimate = pose_model_.published();
  output.pose_estimate.id = output.vehicle.id;
  output.pose_estimate.pose = estimate.pose;
  output.pose_estimate.linear_velocity = estimate.linear_velocity;
  output.pose_estimate.angular_velocity = estimate.angular_velocity;
  output.pose_estimate_utime = settings_.epoch_utime + estimate.time_ns / 1000;
  pose_model_.addJitter(output.pose_estimate.pose);
  return output;
}

std::vector<lidar::Vlp16Return> Simulator::takeReturns()
{
  std::vector<lidar::Vlp16Return> taken;
  taken.swap(returns_);
  return taken;
}

}  // namespace ifar::sim
