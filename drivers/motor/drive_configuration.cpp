#include "drivers/motor/drive_configuration.hpp"

namespace ifar::motor {
namespace {

// A signed object's bytes, as the SDO carries them.
std::uint32_t bitsOf(std::int16_t value)
{
  return static_cast<std::uint16_t>(value);
}
std::uint32_t bitsOf(std::int8_t value)
{
  return static_cast<std::uint8_t>(value);
}

}  // namespace

std::vector<SdoWrite> driveConfigurationWrites(const DriveSetup& setup)
{
  return {
      {kObjectModesOfOperation, 0, bitsOf(kModeProfileVelocity), 1},
      {kObjectMaxProfileVelocity, 0, setup.max_velocity, 4},
      {kObjectProfileAcceleration, 0, setup.acceleration, 4},
      {kObjectProfileDeceleration, 0, setup.deceleration, 4},
      {kObjectQuickStopDeceleration, 0, setup.quick_stop_deceleration, 4},
      {kObjectQuickStopOption, 0, bitsOf(kQuickStopThenSwitchOnDisabled), 2},
      // A lost master stops the wheel on the quick-stop ramp; the node stays operational so its
      // heartbeat, TPDO1 and EMCY keep telling what happened.
      {kObjectAbortConnectionOption, 0, bitsOf(kAbortConnectionQuickStop), 2},
      {kObjectErrorBehaviour, kSubCommunicationError, kCommunicationErrorNoStateChange, 1},
      {kObjectConsumerHeartbeatTime, kSubConsumerHeartbeat1,
       consumerHeartbeatEntry(setup.master_node_id, setup.master_heartbeat_timeout_ms), 4},
      {kObjectRpdo1Communication, kSubEventTimer, setup.rpdo_timeout_ms, 2},
  };
}

}  // namespace ifar::motor
