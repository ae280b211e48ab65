#pragma once
// The vehicle's two wheel drives as one: (v, omega) in, both nodes' frames out. When either side is not
// running (fault, lost heartbeat, still enabling), the other side is held at zero velocity too, so a
// one-sided stop never turns into a spin. Pure, like MotorClient.

#include <cstdint>
#include <vector>

#include "drivers/can/frame.hpp"
#include "drivers/motor/motor_client.hpp"

namespace ifar::motor {

/// Client settings for `node_id`, other fields at their defaults.
inline MotorClientSettings clientSettingsForNode(std::uint8_t node_id)
{
  MotorClientSettings settings;
  settings.node_id = node_id;
  return settings;
}

struct DifferentialDriveSettings {
  MotorClientSettings left = clientSettingsForNode(1);
  MotorClientSettings right = clientSettingsForNode(2);
  double wheel_track_m = 0.6;
  double wheel_radius_m = 0.15;
};

class DifferentialDrive {
 public:
  /// Throws std::invalid_argument when both sides have the same node id or a node id outside 1..127.
  explicit DifferentialDrive(const DifferentialDriveSettings& settings);

  void onFrame(const can::Frame& frame, std::int64_t now_us);
  /// A fresh body velocity command: linear m/s (forward), angular rad/s (counter-clockwise).
  void command(double linear_m_per_s, double angular_rad_per_s, std::int64_t now_us);
  void setEnabled(bool enabled);
  void requestFaultReset();
  /// Frames to send now, left node's first.
  std::vector<can::Frame> update(std::int64_t now_us);

  /// True when both drives run the commanded velocities.
  bool running(std::int64_t now_us) const;
  MotorStatus leftStatus(std::int64_t now_us) const { return left_.status(now_us); }
  MotorStatus rightStatus(std::int64_t now_us) const { return right_.status(now_us); }

 private:
  DifferentialDriveSettings settings_;
  MotorClient left_;
  MotorClient right_;
  WheelVelocities wheels_;
  bool has_command_ = false;
  std::int64_t last_command_us_ = 0;
};

}  // namespace ifar::motor
