#pragma once
// A CiA 402 wheel drive in profile velocity mode as the simulator and the tests need it: the node side
// of the motor link. NMT (boot-up, pre-operational, operational, stopped), heartbeat 0x700+n, RPDO1
// (controlword, target velocity) accepted only when operational, TPDO1 (statusword, actual velocity),
// the statusword state machine, EMCY on injected faults and on fault reset, and an SDO server for the
// objects the motor client writes at start-up (drive_objects.hpp), which it honours:
//
// - the target velocity is limited to 0x607F; the velocity demand ramps toward it at 0x6083 / 0x6084
//   (0x6085 in a quick stop);
// - consumer heartbeat (0x1016:01): once the watched node's first heartbeat has arrived, a gap longer
//   than its time is a heartbeat error (EMCY 0x8130);
// - RPDO deadline (0x1400:05 event timer): once the first RPDO1 has arrived in operational, a gap longer
//   than the timer is an RPDO timeout (EMCY 0x8250);
// - on either, the abort connection option (0x6007: none, fault, disable voltage, quick stop) and the
//   NMT reaction (0x1029:01) apply; leaving operational by NMT applies 0x6007 too; a quick stop ends in
//   switch on disabled (0x605A = 2), so the drive runs again only through the enable sequence 0x06, 0x07,
//   0x0F. When the watched traffic is back, the drive sends EMCY 0x0000 (error reset).
//
// Pure: fed with frames and time, it returns the frames to send, so it runs in lock-step in the
// simulator and without sockets in tests.
//
//   DriveEmulator drive({.node_id = 1});
//   for each received frame: drive.onFrame(frame, now_us);
//   every cycle (e.g. 10 ms): for (const auto& frame : drive.update(now_us)) bus.send(frame);
//   physics: wheel speed command = drive.velocityDemand() (0 unless operation enabled or stopping);
//            drive.setActualVelocity(measured) when the simulator models the wheel itself.

#include <cstdint>
#include <vector>

#include "drivers/can/frame.hpp"
#include "drivers/motor/canopen_frames.hpp"
#include "sim/can_nodes/drive_objects.hpp"

namespace ifar::sim {

struct DriveEmulatorSettings {
  std::uint8_t node_id = 1;
  std::int64_t heartbeat_period_us = 100'000;  // object 0x1017
  std::int64_t tpdo_period_us = 10'000;        // TPDO1 event timer
  /// When true, actual velocity ramps toward the velocity demand at `acceleration` per second; when
  /// false, actual velocity is whatever setActualVelocity() last set (a simulator models the wheel).
  bool model_velocity = true;
  double acceleration = 20'000.0;  // drive units (0.001 rad/s) per second
};

class DriveEmulator {
 public:
  explicit DriveEmulator(const DriveEmulatorSettings& settings = {});

  /// Feeds one received frame (NMT, this node's RPDO1 and SDO requests, the watched heartbeat; anything
  /// else is ignored).
  void onFrame(const can::Frame& frame, std::int64_t now_us);
  /// Advances time: watchdogs, the velocity ramp; returns frames to send now (boot-up, EMCY, SDO
  /// answers, heartbeat, TPDO1).
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
  motor::NmtState nmtState() const { return nmt_state_; }
  motor::DriveState driveState() const { return drive_state_; }
  std::uint16_t statusword() const { return motor::statuswordFor(drive_state_); }
  /// What the velocity profile aims at: the target (limited to 0x607F) when operation is enabled, else 0.
  std::int32_t commandedVelocity() const;
  /// The profile's output (0x606B), what the power stage is asked for now: ramps toward
  /// commandedVelocity() at the configured accelerations; 0 at once when the power stage is off.
  std::int32_t velocityDemand() const;
  std::int32_t actualVelocity() const { return actual_velocity_; }
  std::int32_t targetVelocity() const { return target_velocity_; }
  std::uint16_t lastControlword() const { return last_controlword_; }
  const DriveObjects& objects() const { return objects_; }
  /// RPDOs, NMT and SDO frames for this node that had the wrong length.
  std::int64_t badFrames() const { return bad_frames_; }

 private:
  void onNmt(const can::Frame& frame);
  void onRpdo(const can::Frame& frame, std::int64_t now_us);
  void onSdo(const can::Frame& frame);
  void onWatchedHeartbeat(std::int64_t now_us);
  void applyControlword(std::uint16_t controlword);
  void resetNode();
  void leaveOperational(motor::NmtState next);
  void checkWatchdogs(std::int64_t now_us);
  void abortConnection();
  void communicationError(std::uint16_t error_code, unsigned error_bit);
  void communicationRestored(unsigned error_bit);
  void advanceVelocity(std::int64_t now_us);
  void emit(std::vector<can::Frame>& frames, std::int64_t now_us);

  DriveEmulatorSettings settings_;
  DriveObjects objects_;
  motor::NmtState nmt_state_ = motor::NmtState::kBootUp;
  motor::DriveState drive_state_ = motor::DriveState::kSwitchOnDisabled;
  bool boot_up_pending_ = true;
  bool transmitting_ = true;
  bool heartbeat_enabled_ = true;
  std::int64_t next_heartbeat_us_ = 0;
  std::int64_t next_tpdo_us_ = 0;
  std::int64_t last_update_us_ = -1;
  std::uint16_t last_controlword_ = 0;
  std::int32_t target_velocity_ = 0;
  std::int32_t actual_velocity_ = 0;
  double demand_ = 0.0;
  std::uint16_t fault_code_ = 0;
  // Watchdogs: the last watched heartbeat and RPDO, and whether each is being watched (it starts with
  // the first one after configuration and pauses after an error until the next one arrives).
  std::int64_t last_watched_heartbeat_us_ = 0;
  bool heartbeat_watched_ = false;
  std::int64_t last_rpdo_us_ = 0;
  bool rpdo_watched_ = false;
  unsigned communication_errors_ = 0;  // bit set per watchdog that tripped and has not recovered
  std::vector<motor::Emergency> pending_emergencies_;
  std::vector<can::Frame> pending_sdo_answers_;
  std::int64_t bad_frames_ = 0;
  double modelled_velocity_ = 0.0;
};

}  // namespace ifar::sim
