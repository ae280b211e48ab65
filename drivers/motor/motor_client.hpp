#pragma once
// The CANopen CiA 402 velocity-mode client for one drive (node), as the executive uses it. A pure state
// machine fed with received frames, velocity commands and time; update() returns the frames to send.
//
// Each cycle (call update() every 10-20 ms) the client:
//  - once the drive's heartbeat is seen, writes its start-up configuration by SDO (limits, watchdogs;
//    drive_configuration.hpp), one object at a time, and enables nothing until every write is confirmed;
//    a drive that reboots is configured again,
//  - starts the node (NMT start) when its heartbeat shows it is not operational (retried at a rate),
//  - walks the enable sequence from the statusword of TPDO1: shutdown 0x06 -> ready to switch on,
//    switch on 0x07 -> switched on, enable operation 0x0F -> operation enabled,
//  - sends RPDO1 (controlword, target velocity) cyclically, the velocity never beyond max_velocity,
//  - and performs a safe stop (zero velocity until standstill or stop_timeout, then shutdown 0x06) on a
//    drive fault (statusword or EMCY), a lost heartbeat, a stale command, or setEnabled(false); a drive
//    found enabled while no fresh command has arrived (a restarted motor driver) is stopped the same way.
// Faults latch until requestFaultReset(); the client then sends the fault-reset edge (0x80) and
// re-enables. A lost heartbeat or stale command clears by itself once heartbeats and fresh commands
// are back: the client runs only while commands keep arriving. An EMCY for a communication error
// (0x81xx, 0x82xx: the drive's own watchdog stopped it) does not latch: the drive is back in switch on
// disabled, and the client walks the enable sequence again once commands are fresh.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "drivers/can/frame.hpp"
#include "drivers/motor/canopen_frames.hpp"
#include "drivers/motor/drive_configurator.hpp"
#include "drivers/motor/sdo.hpp"

namespace ifar::motor {

struct MotorClientSettings {
  std::uint8_t node_id = 1;
  std::int64_t heartbeat_timeout_us = 300'000;  // consumer time: 3 producer periods of 100 ms
  std::int64_t command_timeout_us = 200'000;    // a command older than this is stale
  std::int64_t stop_timeout_us = 1'000'000;     // zero velocity at most this long before disabling
  std::int32_t standstill_velocity = 20;        // |actual| at or below this (0.001 rad/s) is standstill
  std::int64_t nmt_retry_us = 500'000;          // NMT start is repeated at most this often
  /// |RPDO1 target velocity| never exceeds this (0.001 rad/s), whatever command() was given.
  std::int32_t max_velocity = std::numeric_limits<std::int32_t>::max();
  /// Written by SDO before the drive is enabled (drive_configuration.hpp); empty = nothing to write.
  std::vector<SdoWrite> configuration;
  std::int64_t sdo_timeout_us = 50'000;             // an SDO answer later than this is a timeout
  int sdo_attempts = 3;                             // tries per object
  std::int64_t configuration_retry_us = 1'000'000;  // a failed configuration starts over after this
};

enum class ClientPhase {
  kWaitingForDrive,  // no heartbeat yet, or starting the node
  kConfiguring,      // writing the start-up configuration by SDO
  kEnabling,         // walking the enable sequence
  kRunning,          // operation enabled, the commanded velocity is sent
  kStopping,         // safe stop: zero velocity until standstill
  kStopped,          // safe stop done: disabled (shutdown), zero velocity
};
const char* toString(ClientPhase phase);

enum class StopReason {
  kNone,
  kNotEnabled,
  kStaleCommand,
  kHeartbeatLost,
  kDriveFault,
  kConfiguring,          // the start-up configuration is not confirmed yet
  kConfigurationFailed,  // the drive refused or did not answer it (MotorStatus::configuration_error)
};
const char* toString(StopReason reason);

struct MotorStatus {
  std::uint8_t node_id = 0;
  std::optional<NmtState> nmt_state;  // from the last heartbeat
  bool heartbeat_ok = false;
  std::optional<std::uint16_t> statusword;  // from the last TPDO1
  DriveState drive_state = DriveState::kNotReadyToSwitchOn;
  std::int32_t target_velocity = 0;         // last sent on RPDO1
  std::int32_t actual_velocity = 0;         // last received on TPDO1
  std::optional<std::int64_t> feedback_us;  // when the last TPDO1 arrived (the clock of onFrame's now_us)
  std::uint16_t emergency_code = 0;         // last EMCY error code, 0 when none or reset
  bool fault_latched = false;
  ClientPhase phase = ClientPhase::kWaitingForDrive;
  StopReason reason = StopReason::kNone;  // why the client stops or would stop now; kNone = healthy
  bool configured = false;                // every start-up SDO write confirmed
  std::string configuration_error;        // why the last configuration failed; empty when none did
  std::int64_t bad_frames = 0;            // frames on this node's COB-IDs with a wrong length or content
  std::int64_t ignored_frames = 0;        // frames of other ids (other nodes, unknown ids), skipped
  std::int64_t sdo_timeouts = 0;          // SDO transfers repeated after a timeout
};

class MotorClient {
 public:
  explicit MotorClient(const MotorClientSettings& settings = {});

  /// Feeds one received frame; frames of other nodes and unknown ids are counted and skipped.
  void onFrame(const can::Frame& frame, std::int64_t now_us);
  /// A fresh velocity command in drive units (0.001 rad/s at the wheel). Keep sending: it goes stale.
  void command(std::int32_t target_velocity, std::int64_t now_us);
  /// Operator enable/disable (e-stop). Disabled = safe stop and no re-enable until enabled again.
  void setEnabled(bool enabled) { enabled_ = enabled; }
  /// Clears a latched fault; the next updates send the fault-reset edge and re-enable.
  void requestFaultReset();
  /// Advances the state machine; returns the frames to send now (NMT, RPDO1).
  std::vector<can::Frame> update(std::int64_t now_us);

  MotorStatus status(std::int64_t now_us) const;
  std::uint8_t nodeId() const { return settings_.node_id; }

 private:
  bool heartbeatOk(std::int64_t now_us) const;
  bool commandFresh(std::int64_t now_us) const;
  StopReason stopReason(std::int64_t now_us) const;
  void latchFault(std::uint16_t code);
  void onEmergency(const Emergency& emergency);
  can::Frame rpdo(std::uint16_t controlword, std::int32_t velocity);
  std::vector<can::Frame> stopFrames(StopReason reason, DriveState drive_state, std::int64_t now_us);
  std::vector<can::Frame> runFrames(DriveState drive_state, std::int64_t now_us);

  MotorClientSettings settings_;
  DriveConfigurator configurator_;
  bool enabled_ = true;
  std::optional<NmtState> nmt_state_;
  std::int64_t last_heartbeat_us_ = 0;
  std::optional<std::uint16_t> statusword_;
  std::int32_t actual_velocity_ = 0;
  std::optional<std::int64_t> feedback_us_;
  std::optional<std::int64_t> last_command_us_;
  std::int32_t commanded_velocity_ = 0;
  std::int32_t sent_velocity_ = 0;
  std::uint16_t sent_controlword_ = 0;
  bool fault_latched_ = false;
  bool fault_reset_pending_ = false;
  std::uint16_t emergency_code_ = 0;
  ClientPhase phase_ = ClientPhase::kWaitingForDrive;
  StopReason reason_ = StopReason::kNone;
  std::int64_t stop_started_us_ = 0;
  std::optional<std::int64_t> last_nmt_start_us_;
  std::int64_t bad_frames_ = 0;
  std::int64_t ignored_frames_ = 0;
};

/// Wheel speeds for a differential drive, in drive units (0.001 rad/s at the wheel, positive = the
/// wheel rolls the vehicle forward): left = (v - omega * track / 2) / radius, right likewise with +.
struct WheelVelocities {
  std::int32_t left = 0;
  std::int32_t right = 0;
};
WheelVelocities wheelVelocities(double linear_m_per_s, double angular_rad_per_s, double wheel_track_m,
                                double wheel_radius_m);

}  // namespace ifar::motor
