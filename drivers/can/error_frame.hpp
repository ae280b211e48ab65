#pragma once
// Decoding of SocketCAN error frames (linux/can/error.h layout) into the controller's bus state.
// Pure functions, so the decoding is testable without a kernel.

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_bus.hpp"
#include "drivers/can/frame.hpp"

namespace ifar::can {

/// Error class bits carried in an error frame's id (values of linux/can/error.h CAN_ERR_*).
constexpr std::uint32_t kErrorTxTimeout = 0x001;
constexpr std::uint32_t kErrorLostArbitration = 0x002;
constexpr std::uint32_t kErrorController = 0x004;
constexpr std::uint32_t kErrorProtocol = 0x008;
constexpr std::uint32_t kErrorTransceiver = 0x010;
constexpr std::uint32_t kErrorNoAck = 0x020;
constexpr std::uint32_t kErrorBusOff = 0x040;
constexpr std::uint32_t kErrorBusError = 0x080;
constexpr std::uint32_t kErrorRestarted = 0x100;
/// Controller status bits in data[1] when kErrorController is set.
constexpr std::uint8_t kControllerRxWarning = 0x04;
constexpr std::uint8_t kControllerTxWarning = 0x08;
constexpr std::uint8_t kControllerRxPassive = 0x10;
constexpr std::uint8_t kControllerTxPassive = 0x20;
constexpr std::uint8_t kControllerActive = 0x40;

/// The state after `frame` given the state before it; nullopt when the frame says nothing about the
/// state (for example a protocol error or lost arbitration alone).
std::optional<BusState> stateAfterErrorFrame(const Frame& frame, BusState before);

/// A short description for logs: "bus-off", "controller: tx-passive", "no-ack", ...
std::string describeErrorFrame(const Frame& frame);

/// An error frame as the kernel would send it (for emulation and tests).
Frame makeErrorFrame(std::uint32_t error_class, std::uint8_t controller_status = 0);

}  // namespace ifar::can
