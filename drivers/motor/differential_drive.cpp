#include "drivers/motor/differential_drive.hpp"

#include <stdexcept>
#include <string>

namespace ifar::motor {
namespace {

DifferentialDriveSettings checked(const DifferentialDriveSettings& settings)
{
  for (const std::uint8_t node_id : {settings.left.node_id, settings.right.node_id}) {
    if (node_id < 1 || node_id > 127) {
      throw std::invalid_argument("DifferentialDrive: node id " + std::to_string(node_id) +
                                  " is outside 1..127");
    }
  }
  if (settings.left.node_id == settings.right.node_id) {
    throw std::invalid_argument("DifferentialDrive: left and right drives both have node id " +
                                std::to_string(settings.left.node_id));
  }
  return settings;
}

}  // namespace

DifferentialDrive::DifferentialDrive(const DifferentialDriveSettings& settings)
    : settings_(checked(settings)), left_(settings.left), right_(settings.right)
{
}

void DifferentialDrive::onFrame(const can::Frame& frame, std::int64_t now_us)
{
  left_.onFrame(frame, now_us);
  right_.onFrame(frame, now_us);
}

void DifferentialDrive::command(double linear_m_per_s, double angular_rad_per_s, std::int64_t now_us)
{
  wheels_ =
      wheelVelocities(linear_m_per_s, angular_rad_per_s, settings_.wheel_track_m, settings_.wheel_radius_m);
  has_command_ = true;
  last_command_us_ = now_us;
}

void DifferentialDrive::setEnabled(bool enabled)
{
  left_.setEnabled(enabled);
  right_.setEnabled(enabled);
}

void DifferentialDrive::requestFaultReset()
{
  left_.requestFaultReset();
  right_.requestFaultReset();
}

bool DifferentialDrive::running(std::int64_t now_us) const
{
  // A side whose stop reason arrived since its last update() counts as stopped already.
  const auto side_running = [now_us](const MotorClient& client) {
    const MotorStatus status = client.status(now_us);
    return status.phase == ClientPhase::kRunning && status.reason == StopReason::kNone;
  };
  return side_running(left_) && side_running(right_);
}

std::vector<can::Frame> DifferentialDrive::update(std::int64_t now_us)
{
  if (has_command_) {
    // Commands keep their own timestamp so staleness is judged on when the executive last spoke.
    const bool both_running = running(now_us);
    left_.command(both_running ? wheels_.left : 0, last_command_us_);
    right_.command(both_running ? wheels_.right : 0, last_command_us_);
  }
  std::vector<can::Frame> frames = left_.update(now_us);
  for (const can::Frame& frame : right_.update(now_us)) {
    frames.push_back(frame);
  }
  return frames;
}

}  // namespace ifar::motor
