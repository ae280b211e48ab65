#pragma once
// The motor driver's node core: VELOCITY_CMD in, the drives' CANopen frames out and MOTOR_STATUS, without
// a bus. The daemon (motor_driver_main.cpp) wraps it around the configured CAN bus; the headless runner
// (system/) feeds it on simulated time. One clock, `now_us`: microseconds.

#include <cstdint>
#include <vector>

#include "common/vehicle.hpp"
#include "drivers/can/frame.hpp"
#include "drivers/motor/differential_drive.hpp"
#include "drivers/motor/motor_config.hpp"
#include "ifar/motor_status_t.hpp"
#include "ifar/velocity_cmd_t.hpp"

namespace ifar::motor {

class MotorDriverNode {
 public:
  MotorDriverNode(const MotorConfig& config, const common::VehicleSettings& vehicle);

  void onVelocityCommand(const ifar::velocity_cmd_t& command, std::int64_t now_us);
  void onFrame(const can::Frame& frame, std::int64_t now_us);
  /// Call every motor.cycle_ms: the frames to send now.
  std::vector<can::Frame> cycle(std::int64_t now_us);
  /// Call every 100 ms: one motor_status_t per drive.
  std::vector<ifar::motor_status_t> statusMessages(std::int64_t now_us) const;

  std::int64_t commands() const { return commands_; }

 private:
  MotorConfig config_;
  DifferentialDrive drive_;
  std::int64_t commands_ = 0;
};

}  // namespace ifar::motor
