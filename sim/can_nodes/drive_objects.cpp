#include "sim/can_nodes/drive_objects.hpp"

namespace ifar::sim {
namespace {

using motor::SdoWrite;

std::uint32_t writeCommunicationObject(DriveObjects& objects, const SdoWrite& write)
{
  switch (write.index) {
    case motor::kObjectConsumerHeartbeatTime:
      if (write.subindex == 0) {
        return motor::kAbortReadOnly;  // the number of entries
      }
      if (write.subindex != motor::kSubConsumerHeartbeat1) {
        return motor::kAbortNoSubindex;  // this drive watches one producer
      }
      if (write.size != 4) {
        return motor::kAbortLengthMismatch;
      }
      if ((write.value >> 24) != 0) {
        return motor::kAbortValueRange;  // bits 31-24 are reserved
      }
      objects.consumer_heartbeat = write.value;
      return 0;
    case motor::kObjectErrorBehaviour:
      if (write.subindex != motor::kSubCommunicationError) {
        return write.subindex == 0 ? motor::kAbortReadOnly : motor::kAbortNoSubindex;
      }
      if (write.size != 1) {
        return motor::kAbortLengthMismatch;
      }
      if (write.value > motor::kCommunicationErrorStopped) {
        return motor::kAbortValueRange;
      }
      objects.communication_error_behaviour = static_cast<std::uint8_t>(write.value);
      return 0;
    case motor::kObjectRpdo1Communication:
      if (write.subindex != motor::kSubEventTimer) {
        // The PDO's COB-ID, transmission type and inhibit time are fixed in this drive.
        return write.subindex <= 3 ? motor::kAbortReadOnly : motor::kAbortNoSubindex;
      }
      if (write.size != 2) {
        return motor::kAbortLengthMismatch;
      }
      objects.rpdo_event_timer_ms = static_cast<std::uint16_t>(write.value);
      return 0;
    default:
      return motor::kAbortNoObject;
  }
}

std::uint32_t writeLimit(std::uint32_t& object, const SdoWrite& write, std::uint32_t minimum)
{
  if (write.size != 4) {
    return motor::kAbortLengthMismatch;
  }
  if (write.value < minimum) {
    return motor::kAbortValueRange;
  }
  object = write.value;
  return 0;
}

std::uint32_t writeDriveProfileObject(DriveObjects& objects, const SdoWrite& write)
{
  if (write.subindex != 0) {
    return motor::kAbortNoSubindex;
  }
  const auto as_int16 = static_cast<std::int16_t>(static_cast<std::uint16_t>(write.value));
  switch (write.index) {
    case motor::kObjectModesOfOperation:
      if (write.size != 1) {
        return motor::kAbortLengthMismatch;
      }
      if (static_cast<std::int8_t>(write.value) != motor::kModeProfileVelocity) {
        return motor::kAbortValueRange;  // profile velocity is the one mode emulated
      }
      objects.mode_of_operation = motor::kModeProfileVelocity;
      return 0;
    case motor::kObjectMaxProfileVelocity:
      return writeLimit(objects.max_profile_velocity, write, 0);
    case motor::kObjectProfileAcceleration:
      return writeLimit(objects.profile_acceleration, write, 1);
    case motor::kObjectProfileDeceleration:
      return writeLimit(objects.profile_deceleration, write, 1);
    case motor::kObjectQuickStopDeceleration:
      return writeLimit(objects.quick_stop_deceleration, write, 1);
    case motor::kObjectQuickStopOption:
      if (write.size != 2) {
        return motor::kAbortLengthMismatch;
      }
      if (as_int16 != motor::kQuickStopThenSwitchOnDisabled) {
        return motor::kAbortValueRange;  // the one quick stop reaction emulated
      }
      objects.quick_stop_option = as_int16;
      return 0;
    case motor::kObjectAbortConnectionOption:
      if (write.size != 2) {
        return motor::kAbortLengthMismatch;
      }
      if (as_int16 < motor::kAbortConnectionNoAction || as_int16 > motor::kAbortConnectionQuickStop) {
        return motor::kAbortValueRange;
      }
      objects.abort_connection_option = as_int16;
      return 0;
    default:
      return motor::kAbortNoObject;
  }
}

}  // namespace

std::int64_t DriveObjects::heartbeatTimeoutUs() const
{
  const std::uint8_t node = watchedNode();
  const std::uint32_t time_ms = consumer_heartbeat & 0xFFFF;
  return node >= 1 && node <= 127 ? static_cast<std::int64_t>(time_ms) * 1000 : 0;
}

std::uint32_t writeDriveObject(DriveObjects& objects, const motor::SdoWrite& write)
{
  if (write.index >= 0x6000) {
    return writeDriveProfileObject(objects, write);
  }
  return writeCommunicationObject(objects, write);
}

}  // namespace ifar::sim
