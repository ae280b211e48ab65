#pragma once
// What the motor client writes into each drive at start-up, by SDO, before it enables it: the drive's
// own speed and acceleration limits (CiA 402) and its watchdogs on the motor driver (CiA 301), so a
// drive stops by itself when the motor driver freezes or dies. The drive emulator implements the same
// objects. Values and the timing budget: docs/can_frames.md, "Start-up configuration".

#include <cstdint>
#include <vector>

#include "drivers/motor/sdo.hpp"

namespace ifar::motor {

// CiA 301 communication objects.
constexpr std::uint16_t kObjectConsumerHeartbeatTime = 0x1016;  // sub 1: u32, (node id << 16) | time in ms
constexpr std::uint16_t kObjectErrorBehaviour = 0x1029;  // sub 1: u8, NMT reaction to a communication error
constexpr std::uint16_t kObjectRpdo1Communication = 0x1400;  // sub 5: u16 event timer in ms (deadline)
// CiA 402 drive objects.
constexpr std::uint16_t kObjectAbortConnectionOption = 0x6007;  // i16, reaction to a communication error
constexpr std::uint16_t kObjectQuickStopOption = 0x605A;        // i16, what a quick stop ends in
constexpr std::uint16_t kObjectModesOfOperation = 0x6060;       // i8
constexpr std::uint16_t kObjectMaxProfileVelocity = 0x607F;     // u32, velocity units (0.001 rad/s)
constexpr std::uint16_t kObjectProfileAcceleration = 0x6083;    // u32, acceleration units (0.001 rad/s^2)
constexpr std::uint16_t kObjectProfileDeceleration = 0x6084;    // u32
constexpr std::uint16_t kObjectQuickStopDeceleration = 0x6085;  // u32

constexpr std::uint8_t kSubConsumerHeartbeat1 = 1;
constexpr std::uint8_t kSubCommunicationError = 1;
constexpr std::uint8_t kSubEventTimer = 5;

// Values with a meaning of their own.
constexpr std::int8_t kModeProfileVelocity = 3;                // 0x6060
constexpr std::int16_t kAbortConnectionNoAction = 0;           // 0x6007 ...
constexpr std::int16_t kAbortConnectionFault = 1;              //   fault signal
constexpr std::int16_t kAbortConnectionDisableVoltage = 2;     //   disable voltage command
constexpr std::int16_t kAbortConnectionQuickStop = 3;          //   quick stop command
constexpr std::int16_t kQuickStopThenSwitchOnDisabled = 2;     // 0x605A: quick stop ramp, then disabled
constexpr std::uint8_t kCommunicationErrorPreOperational = 0;  // 0x1029:01 ...
constexpr std::uint8_t kCommunicationErrorNoStateChange = 1;
constexpr std::uint8_t kCommunicationErrorStopped = 2;

/// Consumer heartbeat entry (0x1016:n): watch `node_id`'s heartbeat, at most `time_ms` between two.
constexpr std::uint32_t consumerHeartbeatEntry(std::uint8_t node_id, std::uint16_t time_ms)
{
  return (static_cast<std::uint32_t>(node_id) << 16) | time_ms;
}

/// One drive's start-up configuration, in drive units.
struct DriveSetup {
  std::uint32_t max_velocity = 0;                 // 0x607F, 0.001 rad/s at the wheel
  std::uint32_t acceleration = 0;                 // 0x6083, 0.001 rad/s^2
  std::uint32_t deceleration = 0;                 // 0x6084
  std::uint32_t quick_stop_deceleration = 0;      // 0x6085, used when the watchdog stops the drive
  std::uint8_t master_node_id = 127;              // whose heartbeat the drive watches
  std::uint16_t master_heartbeat_timeout_ms = 0;  // 0x1016:01; 0 = not watched
  std::uint16_t rpdo_timeout_ms = 0;              // 0x1400:05; 0 = not watched
};

/// The writes, in the order the client sends them: mode and limits first, then the reaction to a
/// communication error, the watchdogs last (they start watching once they are set).
std::vector<SdoWrite> driveConfigurationWrites(const DriveSetup& setup);

}  // namespace ifar::motor
