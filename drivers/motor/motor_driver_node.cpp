#include "drivers/motor/motor_driver_node.hpp"

#include "drivers/motor/motor_status_message.hpp"

namespace ifar::motor {

MotorDriverNode::MotorDriverNode(const MotorConfig& config, const common::VehicleSettings& vehicle)
    : config_(config), drive_([&] {
        DifferentialDriveSettings settings = config.drive;
        settings.wheel_track_m = vehicle.wheel_track_m;
        settings.wheel_radius_m = vehicle.wheel_radius_m;
        return settings;
      }())
{
}

void MotorDriverNode::onVelocityCommand(const ifar::velocity_cmd_t& command, std::int64_t now_us)
{
  drive_.command(command.linear_velocity, command.angular_velocity, now_us);
  ++commands_;
}

void MotorDriverNode::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  drive_.onFrame(frame, now_us);
}

std::vector<can::Frame> MotorDriverNode::cycle(std::int64_t now_us)
{
  return drive_.update(now_us);
}

std::vector<ifar::motor_status_t> MotorDriverNode::statusMessages(std::int64_t now_us) const
{
  return {toMessage(drive_.leftStatus(now_us), now_us), toMessage(drive_.rightStatus(now_us), now_us)};
}

}  // namespace ifar::motor
