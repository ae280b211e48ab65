#pragma once
// The part of a CiA 402 drive's object dictionary the simulated drive implements: what the motor client
// writes at start-up (drivers/motor/drive_configuration.hpp) with the checks a drive makes on an SDO
// download. Defaults are what the emulator does unconfigured: no limits, no watchdogs.

#include <cstdint>
#include <limits>

#include "drivers/motor/drive_configuration.hpp"
#include "drivers/motor/sdo.hpp"

namespace ifar::sim {

struct DriveObjects {
  std::int8_t mode_of_operation = motor::kModeProfileVelocity;                        // 0x6060
  std::uint32_t max_profile_velocity = std::numeric_limits<std::uint32_t>::max();     // 0x607F
  std::uint32_t profile_acceleration = std::numeric_limits<std::uint32_t>::max();     // 0x6083, max = no ramp
  std::uint32_t profile_deceleration = std::numeric_limits<std::uint32_t>::max();     // 0x6084
  std::uint32_t quick_stop_deceleration = std::numeric_limits<std::uint32_t>::max();  // 0x6085
  std::int16_t quick_stop_option = motor::kQuickStopThenSwitchOnDisabled;             // 0x605A
  std::int16_t abort_connection_option = motor::kAbortConnectionDisableVoltage;       // 0x6007
  std::uint8_t communication_error_behaviour = motor::kCommunicationErrorPreOperational;  // 0x1029:01
  std::uint32_t consumer_heartbeat = 0;   // 0x1016:01, (node id << 16) | ms; 0 = not watched
  std::uint16_t rpdo_event_timer_ms = 0;  // 0x1400:05; 0 = no deadline

  /// The watched producer and its time, when 0x1016:01 names one (node 1..127, time > 0).
  std::uint8_t watchedNode() const { return static_cast<std::uint8_t>((consumer_heartbeat >> 16) & 0xFF); }
  std::int64_t heartbeatTimeoutUs() const;
  std::int64_t rpdoTimeoutUs() const { return static_cast<std::int64_t>(rpdo_event_timer_ms) * 1000; }
};

/// Applies one SDO download to `objects`: 0 when written, else the SDO abort code the drive answers with
/// (unknown object or sub-index, read-only entry, wrong length, value out of range). `objects` is
/// unchanged on an abort.
std::uint32_t writeDriveObject(DriveObjects& objects, const motor::SdoWrite& write);

}  // namespace ifar::sim
