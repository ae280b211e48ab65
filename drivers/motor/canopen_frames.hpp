#pragma once
// CANopen (CiA 301) frames the motor client and the drive emulator exchange, with the project's fixed
// PDO mapping (docs/can_frames.md, "Motor controllers"). Encoders build exact bytes; decoders never
// throw and return nullopt for a frame of the wrong id, kind or length.

#include <cstdint>
#include <optional>

#include "drivers/can/frame.hpp"

namespace ifar::motor {

constexpr std::uint32_t kNmtId = 0x000;
constexpr std::uint32_t kEmergencyBase = 0x080;
constexpr std::uint32_t kTpdo1Base = 0x180;
constexpr std::uint32_t kRpdo1Base = 0x200;
constexpr std::uint32_t kHeartbeatBase = 0x700;

/// EMCY error codes (CiA 301) of a drive that lost its master: it stopped the wheel by itself.
constexpr std::uint16_t kEmergencyHeartbeatError = 0x8130;  // no heartbeat within the consumer time
constexpr std::uint16_t kEmergencyRpdoTimeout = 0x8250;     // no RPDO within its event timer (deadline)
/// True for communication (0x81xx) and protocol (0x82xx) errors: trouble on the link, not in the drive.
constexpr bool isCommunicationError(std::uint16_t error_code)
{
  return (error_code & 0xFF00) == 0x8100 || (error_code & 0xFF00) == 0x8200;
}

/// NMT command specifiers (byte 0 of an NMT frame).
enum class NmtCommand : std::uint8_t {
  kStart = 0x01,
  kStop = 0x02,
  kEnterPreOperational = 0x80,
  kResetNode = 0x81,
  kResetCommunication = 0x82,
};

/// NMT states as a heartbeat reports them.
enum class NmtState : std::uint8_t {
  kBootUp = 0x00,
  kStopped = 0x04,
  kOperational = 0x05,
  kPreOperational = 0x7F,
};
const char* toString(NmtState state);

/// CiA 402 controlwords the client sends.
constexpr std::uint16_t kControlDisableVoltage = 0x0000;
constexpr std::uint16_t kControlShutdown = 0x0006;
constexpr std::uint16_t kControlSwitchOn = 0x0007;
constexpr std::uint16_t kControlEnableOperation = 0x000F;
constexpr std::uint16_t kControlFaultReset = 0x0080;

/// CiA 402 drive states, from the statusword.
enum class DriveState {
  kNotReadyToSwitchOn,   // statusword & 0x4F == 0x00
  kSwitchOnDisabled,     // & 0x4F == 0x40
  kReadyToSwitchOn,      // & 0x6F == 0x21
  kSwitchedOn,           // & 0x6F == 0x23
  kOperationEnabled,     // & 0x6F == 0x27
  kQuickStopActive,      // & 0x6F == 0x07
  kFaultReactionActive,  // & 0x4F == 0x0F
  kFault,                // & 0x4F == 0x08
};
const char* toString(DriveState state);
DriveState driveStateFromStatusword(std::uint16_t statusword);
/// A statusword a drive in `state` reports (remote bit 9 and voltage-enabled bit 4 set where they apply).
std::uint16_t statuswordFor(DriveState state);

struct NmtMessage {
  NmtCommand command = NmtCommand::kStart;
  std::uint8_t node_id = 0;  // 0 = every node
};
struct Emergency {
  std::uint16_t error_code = 0;     // 0x0000 = error reset / no error
  std::uint8_t error_register = 0;  // object 0x1001
  std::uint8_t node_id = 0;
};
/// RPDO1: controlword (0x6040) u16 LE, target velocity (0x60FF) i32 LE; 6 bytes.
struct VelocityCommand {
  std::uint16_t controlword = 0;
  std::int32_t target_velocity = 0;  // 0.001 rad/s at the wheel
};
/// TPDO1: statusword (0x6041) u16 LE, actual velocity (0x606C) i32 LE; 6 bytes.
struct VelocityFeedback {
  std::uint16_t statusword = 0;
  std::int32_t actual_velocity = 0;  // 0.001 rad/s at the wheel
};

can::Frame encodeNmt(NmtMessage message);
can::Frame encodeHeartbeat(std::uint8_t node_id, NmtState state);
can::Frame encodeEmergency(const Emergency& emergency);
can::Frame encodeRpdo1(std::uint8_t node_id, const VelocityCommand& command);
can::Frame encodeTpdo1(std::uint8_t node_id, const VelocityFeedback& feedback);

std::optional<NmtMessage> decodeNmt(const can::Frame& frame);
/// For a heartbeat from `node_id`; unknown state bytes are rejected.
std::optional<NmtState> decodeHeartbeat(const can::Frame& frame, std::uint8_t node_id);
std::optional<Emergency> decodeEmergency(const can::Frame& frame, std::uint8_t node_id);
std::optional<VelocityCommand> decodeRpdo1(const can::Frame& frame, std::uint8_t node_id);
std::optional<VelocityFeedback> decodeTpdo1(const can::Frame& frame, std::uint8_t node_id);

/// True when `frame` is a standard data frame on one of `node_id`'s COB-IDs (EMCY, TPDO1, SDO answer,
/// heartbeat).
bool isFromNode(const can::Frame& frame, std::uint8_t node_id);

}  // namespace ifar::motor
