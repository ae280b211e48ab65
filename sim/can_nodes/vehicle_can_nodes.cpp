#include "sim/can_nodes/vehicle_can_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ifar::sim {
namespace {

constexpr double kDriveUnitsPerRadianPerSecond = 1000.0;  // drive velocity unit: 0.001 rad/s

DriveEmulatorSettings driveSettings(std::uint8_t node_id)
{
  DriveEmulatorSettings settings;
  settings.node_id = node_id;
  settings.model_velocity = false;  // the physics models the wheel
  return settings;
}

std::int32_t toDriveUnits(double rim_speed, double radius)
{
  const double units = std::round(rim_speed / radius * kDriveUnitsPerRadianPerSecond);
  const double limit = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  return static_cast<std::int32_t>(std::clamp(units, -limit, limit));
}

}  // namespace

VehicleCanNodes::VehicleCanNodes(const CanNodeSettings& settings)
    : settings_(settings),
      force_sensor_(settings.force_range_n, settings.force_frame_id),
      force_model_(settings.force, settings.seed),
      left_encoder_(settings.wheels, settings.wheel_radius_m),
      right_encoder_(settings.wheels, settings.wheel_radius_m),
      left_(driveSettings(settings.left_node_id)),
      right_(driveSettings(settings.right_node_id))
{
}

void VehicleCanNodes::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  left_.onFrame(frame, now_us);
  right_.onFrame(frame, now_us);
}

std::vector<can::Frame> VehicleCanNodes::update(std::int64_t now_us, double bumper_force_n,
                                                const physics::WheelSpeeds& actual_wheels)
{
  std::vector<can::Frame> frames;
  if (next_force_us_ < 0) {
    next_force_us_ = now_us;
  }
  if (now_us >= next_force_us_) {
    const ForceModelReading reading = force_model_.next(now_us, bumper_force_n);
    if (force_stuck_ && !reading.stuck) {
      // The firmware is back: its counter moves on from the frame it repeated.
      force_sensor_.setCounterFrozen(false);
      force_sensor_.nextFrame(reading.force_n);
    }
    force_stuck_ = reading.stuck;
    force_sensor_.setCounterFrozen(reading.stuck);
    const can::Frame frame = force_sensor_.nextFrame(reading.force_n);
    if (reading.send) {
      frames.push_back(frame);  // a lost frame still used its counter value: the driver sees the gap
    }
    // Keep the 100 Hz grid; skip missed slots rather than bursting after a stall.
    next_force_us_ += settings_.force_period_us;
    if (next_force_us_ <= now_us) {
      next_force_us_ = now_us + settings_.force_period_us;
    }
  }
  left_.setActualVelocity(
      toDriveUnits(left_encoder_.measure(now_us, actual_wheels.left), settings_.wheel_radius_m));
  right_.setActualVelocity(
      toDriveUnits(right_encoder_.measure(now_us, actual_wheels.right), settings_.wheel_radius_m));
  for (auto* drive : {&left_, &right_}) {
    auto drive_frames = drive->update(now_us);
    frames.insert(frames.end(), drive_frames.begin(), drive_frames.end());
  }
  return frames;
}

physics::WheelSpeeds VehicleCanNodes::commandedWheelSpeeds() const
{
  const double scale = settings_.wheel_radius_m / kDriveUnitsPerRadianPerSecond;
  return {left_.velocityDemand() * scale, right_.velocityDemand() * scale};
}

bool VehicleCanNodes::drivesEnabled() const
{
  return left_.driveState() == motor::DriveState::kOperationEnabled &&
         right_.driveState() == motor::DriveState::kOperationEnabled;
}

}  // namespace ifar::sim
