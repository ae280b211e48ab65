#pragma once
// Top-down rigid-body physics of a world (Box2D 2.4, zero gravity, fixed step): static walls, movable
// objects held by Coulomb ground friction, and the vehicle as a differential drive whose two wheels push
// with at most traction x normal load each, so it stalls against an object too heavy to push. The front
// bumper's normal contact force is what the 1-D force sensor measures. Box2D stays out of this header.

#include <cstdint>
#include <memory>
#include <vector>

#include "common/geometry/pose2.hpp"
#include "common/vehicle.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim::physics {

struct PhysicsSettings {
  double step_seconds = 1.0 / 200.0;  // fixed physics step
  int velocity_iterations = 8;
  int position_iterations = 3;
  double gravity = common::kGravity;  // m/s^2, for normal loads (the world itself is top-down)
  double bumper_depth_m = 0.05;       // thickness of the bumper plate at the vehicle's front
  double surface_friction = 0.5;      // object-object and object-wall Coulomb coefficient
  /// Fraction of a wheel's slip velocity the (stiff) motor controller removes per step, before the
  /// traction cap; 0.5 keeps the two coupled wheels stable.
  double wheel_response = 0.5;
  /// Tyre slip: a wheel transmits at most traction limit x (1 - exp(-slip ratio / slip_ratio_scale)),
  /// so under a large push the body moves slower than the wheels turn. 0 = a rigid tyre (only the speed
  /// controller's own slip, the full traction limit at any slip).
  double slip_ratio_scale = 0.0;
};

/// Pose and velocity of one body (world frame; angular velocity counter-clockwise).
struct BodyState {
  std::int64_t id = 0;  // object id; 0 for the vehicle
  geometry::Pose2 pose;
  geometry::Vector linear_velocity = geometry::Vector::Zero();
  double angular_velocity = 0.0;
};

/// Wheel ground speeds in m/s (rim speed: wheel angular velocity x radius), positive forward.
struct WheelSpeeds {
  double left = 0.0;
  double right = 0.0;
};

/// The vehicle's reference point (its pose) is the wheel axle centre, which this model puts at the
/// centre of the rectangular footprint (length_m x width_m); the bumper face is at x = +length_m / 2.
class PhysicsWorld {
 public:
  PhysicsWorld(const World& world, const common::VehicleSettings& vehicle, const PhysicsSettings& settings);
  ~PhysicsWorld();
  PhysicsWorld(PhysicsWorld&&) noexcept;
  PhysicsWorld& operator=(PhysicsWorld&&) noexcept;
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// Body-frame command: linear m/s, angular rad/s, clamped to the vehicle's limits and followed with its
  /// acceleration limits.
  void setVelocityCommand(double linear, double angular);
  /// The same command expressed as wheel rim speeds in m/s.
  void setWheelSpeedCommand(const WheelSpeeds& wheels);

  /// Advances one fixed step of settings().step_seconds.
  void step();

  double timeSeconds() const;
  const PhysicsSettings& settings() const;
  const common::VehicleSettings& vehicleSettings() const;

  BodyState vehicleState() const;
  /// The movable objects in world-file order.
  std::vector<BodyState> objectStates() const;
  /// Normal force on the bumper face during the last step, newtons, >= 0.
  double bumperForce() const;
  /// What the motor encoders see: the wheels turn at the ramped command even when they slip.
  WheelSpeeds wheelSpeeds() const;

 private:
  struct Implementation;
  std::unique_ptr<Implementation> implementation_;
};

}  // namespace ifar::sim::physics
