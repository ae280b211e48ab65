#include "drivers/motor/canopen_frames.hpp"

#include "drivers/motor/sdo.hpp"

namespace ifar::motor {
namespace {

bool isStandardData(const can::Frame& frame)
{
  return !frame.extended() && !frame.remote() && !frame.error();
}

bool validNode(std::uint8_t node_id)
{
  return node_id >= 1 && node_id <= 127;
}

}  // namespace

const char* toString(NmtState state)
{
  switch (state) {
    case NmtState::kBootUp:
      return "boot-up";
    case NmtState::kStopped:
      return "stopped";
    case NmtState::kOperational:
      return "operational";
    case NmtState::kPreOperational:
      return "pre-operational";
  }
  return "unknown";
}

const char* toString(DriveState state)
{
  switch (state) {
    case DriveState::kNotReadyToSwitchOn:
      return "not ready to switch on";
    case DriveState::kSwitchOnDisabled:
      return "switch on disabled";
    case DriveState::kReadyToSwitchOn:
      return "ready to switch on";
    case DriveState::kSwitchedOn:
      return "switched on";
    case DriveState::kOperationEnabled:
      return "operation enabled";
    case DriveState::kQuickStopActive:
      return "quick stop active";
    case DriveState::kFaultReactionActive:
      return "fault reaction active";
    case DriveState::kFault:
      return "fault";
  }
  return "unknown";
}

DriveState driveStateFromStatusword(std::uint16_t statusword)
{
  switch (statusword & 0x4F) {
    case 0x00:
      return DriveState::kNotReadyToSwitchOn;
    case 0x40:
      return DriveState::kSwitchOnDisabled;
    case 0x0F:
      return DriveState::kFaultReactionActive;
    case 0x08:
      return DriveState::kFault;
    default:
      break;
  }
  switch (statusword & 0x6F) {
    case 0x21:
      return DriveState::kReadyToSwitchOn;
    case 0x23:
      return DriveState::kSwitchedOn;
    case 0x27:
      return DriveState::kOperationEnabled;
    case 0x07:
      return DriveState::kQuickStopActive;
    default:
      break;
  }
  // Any other pattern has the fault bit or is not defined by CiA 402: treat it as not ready.
  return (statusword & 0x08) != 0 ? DriveState::kFault : DriveState::kNotReadyToSwitchOn;
}

std::uint16_t statuswordFor(DriveState state)
{
  constexpr std::uint16_t kRemote = 0x0200;
  constexpr std::uint16_t kVoltageEnabled = 0x0010;
  switch (state) {
    case DriveState::kNotReadyToSwitchOn:
      return 0x0000;
    case DriveState::kSwitchOnDisabled:
      return 0x0040 | kRemote;
    case DriveState::kReadyToSwitchOn:
      return 0x0021 | kRemote | kVoltageEnabled;
    case DriveState::kSwitchedOn:
      return 0x0023 | kRemote | kVoltageEnabled;
    case DriveState::kOperationEnabled:
      return 0x0027 | kRemote | kVoltageEnabled;
    case DriveState::kQuickStopActive:
      return 0x0007 | kRemote | kVoltageEnabled;
    case DriveState::kFaultReactionActive:
      return 0x000F | kRemote;
    case DriveState::kFault:
      return 0x0008 | kRemote;
  }
  return 0;
}

can::Frame encodeNmt(NmtMessage message)
{
  return can::makeFrame(kNmtId, {static_cast<std::uint8_t>(message.command), message.node_id});
}

can::Frame encodeHeartbeat(std::uint8_t node_id, NmtState state)
{
  return can::makeFrame(kHeartbeatBase + node_id, {static_cast<std::uint8_t>(state)});
}

can::Frame encodeEmergency(const Emergency& emergency)
{
  can::Frame frame;
  frame.id = kEmergencyBase + emergency.node_id;
  frame.dlc = 8;
  can::writeU16Le(frame.data.data(), emergency.error_code);
  frame.data[2] = emergency.error_register;
  return frame;
}

can::Frame encodeRpdo1(std::uint8_t node_id, const VelocityCommand& command)
{
  can::Frame frame;
  frame.id = kRpdo1Base + node_id;
  frame.dlc = 6;
  can::writeU16Le(frame.data.data(), command.controlword);
  can::writeU32Le(frame.data.data() + 2, static_cast<std::uint32_t>(command.target_velocity));
  return frame;
}

can::Frame encodeTpdo1(std::uint8_t node_id, const VelocityFeedback& feedback)
{
  can::Frame frame;
  frame.id = kTpdo1Base + node_id;
  frame.dlc = 6;
  can::writeU16Le(frame.data.data(), feedback.statusword);
  can::writeU32Le(frame.data.data() + 2, static_cast<std::uint32_t>(feedback.actual_velocity));
  return frame;
}

std::optional<NmtMessage> decodeNmt(const can::Frame& frame)
{
  if (!isStandardData(frame) || frame.id != kNmtId || frame.dlc != 2) {
    return std::nullopt;
  }
  const std::uint8_t command = frame.data[0];
  if (command != 0x01 && command != 0x02 && command != 0x80 && command != 0x81 && command != 0x82) {
    return std::nullopt;
  }
  if (frame.data[1] > 127) {
    return std::nullopt;
  }
  return NmtMessage{static_cast<NmtCommand>(command), frame.data[1]};
}

std::optional<NmtState> decodeHeartbeat(const can::Frame& frame, std::uint8_t node_id)
{
  if (!validNode(node_id) || !isStandardData(frame) || frame.id != kHeartbeatBase + node_id ||
      frame.dlc != 1) {
    return std::nullopt;
  }
  // Bit 7 is the toggle bit of node guarding; heartbeats send it as 0 but tolerate it.
  const std::uint8_t state = frame.data[0] & 0x7F;
  if (state != 0x00 && state != 0x04 && state != 0x05 && state != 0x7F) {
    return std::nullopt;
  }
  return static_cast<NmtState>(state);
}

std::optional<Emergency> decodeEmergency(const can::Frame& frame, std::uint8_t node_id)
{
  if (!validNode(node_id) || !isStandardData(frame) || frame.id != kEmergencyBase + node_id ||
      frame.dlc != 8) {
    return std::nullopt;
  }
  return Emergency{can::readU16Le(frame.data.data()), frame.data[2], node_id};
}

std::optional<VelocityCommand> decodeRpdo1(const can::Frame& frame, std::uint8_t node_id)
{
  if (!validNode(node_id) || !isStandardData(frame) || frame.id != kRpdo1Base + node_id || frame.dlc != 6) {
    return std::nullopt;
  }
  return VelocityCommand{can::readU16Le(frame.data.data()),
                         static_cast<std::int32_t>(can::readU32Le(frame.data.data() + 2))};
}

std::optional<VelocityFeedback> decodeTpdo1(const can::Frame& frame, std::uint8_t node_id)
{
  if (!validNode(node_id) || !isStandardData(frame) || frame.id != kTpdo1Base + node_id || frame.dlc != 6) {
    return std::nullopt;
  }
  return VelocityFeedback{can::readU16Le(frame.data.data()),
                          static_cast<std::int32_t>(can::readU32Le(frame.data.data() + 2))};
}

bool isFromNode(const can::Frame& frame, std::uint8_t node_id)
{
  return validNode(node_id) && isStandardData(frame) &&
         (frame.id == kEmergencyBase + node_id || frame.id == kTpdo1Base + node_id ||
          frame.id == kSdoAnswerBase + node_id || frame.id == kHeartbeatBase + node_id);
}

}  // namespace ifar::motor
