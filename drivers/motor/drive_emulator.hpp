#pragma once
// The node side of the motor link: a CiA 402 drive in velocity mode as the simulator and the tests
// need it. NMT (boot-up, pre-operational, operational, stopped), heartbeat 0x700+n, RPDO1 (controlword,
// target velocity) accepted only when operational, TPDO1 (statusword, actual velocity), the statusword
// state machine, EMCY on injected faults and on fault reset. Pure: fed with frames and time, it
// returns the frames to send, so it runs in lock-step in the simulator and without sockets in tests.
//
//   DriveEmulator drive({.node_id = 1});
//   for each received frame: drive.onFrame(frame, now_us);
//   every cycle (e.g. 10 ms): for (const auto& frame : drive.update(now_us)) bus.send(frame);
//   physics: wheel speed command = drive.commandedVelocity() (0 unless operation enabled);
//            drive.setActualVelocity(measured) when the simulator models the wheel itself.

#include <cstdint>
#include <vector>

#include "drivers/can/frame.hpp"
#include "drivers/motor/canopen_frames.hpp"

namespace ifar::motor {

struct DriveEmulatorSettings {
  std::uint8_t node_id = 1;
  std::int64_t heartbeat_period_us = 100'000;  // object 0x1017
  std::int64_t tpdo_period_us = 10'000;        // TPDO1 event timer
  /// When true, actual velocity ramps toward the commanded one at `acceleration` per second; when
  /// false, actual velocity is whatever setActualVelocity() last set (a simulator models the wheel).
  bool model_velocity = true;
  double acceleration = 20'000.0;  // drive units (0.001 rad/s) per second
};

class DriveEmulator {
 public:
  explicit DriveEmulator(const DriveEmulatorSettings& settings = {});

  /// Feeds one received frame (NMT and this node's RPDO1; everything else is ignored).
  void onFrame(const can::Frame& frame, std::int64_t now_us);
  /// Advances time; returns frames to send now (boot-up, heartbeat, TPDO1, EMCY).
  std::vector<can::Frame> update(std::int64_t now_us);

  /// Puts the drive into fault with `error_code` (e.g. 0x2310 over-current); sends EMCY on next update.
  void injectFault(std::uint16_t error_code);
  /// When false, the drive sends nothing at all (a cut cable or dead node).
  void setTransmitting(bool transmitting) { transmitting_ = transmitting; }
  /// When false, only heartbeats stop (a lost heartbeat with PDOs still flowing).
  void setHeartbeatEnabled(bool enabled) { heartbeat_enabled_ = enabled; }
  void setActualVelocity(std::int32_t velocity)
  {
    actual_velocity_ = velocity;
    modelled_velocity_ = velocity;
  }

  std::uint8_t nodeId() const { return settings_.node_id; }
  NmtState nmtState() const { return nmt_state_; }
  DriveState driveState() const { return drive_state_; }
  std::uint16_t statusword() const { return statuswordFor(drive_state_); }
  /// Velocity the power stage is asked for: the target when operation is enabled, else 0.
  std::int32_t commandedVelocity() const;
  std::int32_t actualVelocity() const { return actual_velocity_; }
  std::int32_t targetVelocity() const { return target_velocity_; }
  std::uint16_t lastControlword() const { return last_controlword_; }
  /// RPDOs and NMT frames for this node that had the wrong length.
  std::int64_t badFrames() const { return bad_frames_; }

 private:
  void applyControlword(std::uint16_t controlword);
  void resetNode();

  DriveEmulatorSettings settings_;
  NmtState nmt_state_ = NmtState::kBootUp;
  DriveState drive_state_ = DriveState::kSwitchOnDisabled;
  bool boot_up_pending_ = true;
  bool transmitting_ = true;
  bool heartbeat_enabled_ = true;
  std::int64_t next_heartbeat_us_ = 0;
  std::int64_t next_tpdo_us_ = 0;
  std::int64_t last_update_us_ = -1;
  std::uint16_t last_controlword_ = 0;
  std::int32_t target_velocity_ = 0;
  std::int32_t actual_velocity_ = 0;
  std::uint16_t fault_code_ = 0;
  std::vector<Emergency> pending_emergencies_;
  std::int64_t bad_frames_ = 0;
  double modelled_velocity_ = 0.0;
};

}  // namespace ifar::motor
