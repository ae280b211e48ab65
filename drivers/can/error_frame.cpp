#include "drivers/can/error_frame.hpp"

namespace ifar::can {

std::optional<BusState> stateAfterErrorFrame(const Frame& frame, BusState /*before*/)
{
  // Every state the kernel reports is absolute, so the state before does not matter today; it is in
  // the signature for controllers that only report changes.
  if (!frame.error()) {
    return std::nullopt;
  }
  if ((frame.id & kErrorBusOff) != 0) {
    return BusState::kBusOff;
  }
  if ((frame.id & kErrorRestarted) != 0) {
    return BusState::kActive;
  }
  if ((frame.id & kErrorController) != 0 && frame.dlc >= 2) {
    const std::uint8_t status = frame.data[1];
    if ((status & (kControllerRxPassive | kControllerTxPassive)) != 0) {
      return BusState::kPassive;
    }
    if ((status & (kControllerRxWarning | kControllerTxWarning)) != 0) {
      return BusState::kWarning;
    }
    if ((status & kControllerActive) != 0) {
      return BusState::kActive;
    }
  }
  return std::nullopt;
}

std::string describeErrorFrame(const Frame& frame)
{
  struct Name {
    std::uint32_t bit;
    const char* text;
  };
  static constexpr Name kNames[] = {
      {kErrorTxTimeout, "tx-timeout"},    {kErrorLostArbitration, "lost-arbitration"},
      {kErrorController, "controller"},   {kErrorProtocol, "protocol"},
      {kErrorTransceiver, "transceiver"}, {kErrorNoAck, "no-ack"},
      {kErrorBusOff, "bus-off"},          {kErrorBusError, "bus-error"},
      {kErrorRestarted, "restarted"},
  };
  std::string text;
  for (const Name& name : kNames) {
    if ((frame.id & name.bit) != 0) {
      if (!text.empty()) {
        text += ", ";
      }
      text += name.text;
      if (name.bit == kErrorController && frame.dlc >= 2) {
        const std::uint8_t status = frame.data[1];
        if ((status & kControllerRxWarning) != 0)
          text += " rx-warning";
        if ((status & kControllerTxWarning) != 0)
          text += " tx-warning";
        if ((status & kControllerRxPassive) != 0)
          text += " rx-passive";
        if ((status & kControllerTxPassive) != 0)
          text += " tx-passive";
        if ((status & kControllerActive) != 0)
          text += " active";
      }
    }
  }
  return text.empty() ? "unspecified error" : text;
}

Frame makeErrorFrame(std::uint32_t error_class, std::uint8_t controller_status)
{
  Frame frame;
  frame.id = error_class;
  frame.flags = kFlagError;
  frame.dlc = kMaxDataLength;  // the kernel always sends error frames with 8 bytes
  frame.data[1] = controller_status;
  return frame;
}

}  // namespace ifar::can
