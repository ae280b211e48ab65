// libFuzzer: every CANopen frame decoder and the motor client fed with arbitrary frames must never
// crash; decoded PDOs must re-encode to the same bytes, decoded SDO downloads to the same object and
// value. (The simulated drive has its own target, sim/can_nodes/fuzz.)
#include <cstdint>
#include <cstdlib>

#include "drivers/motor/canopen_frames.hpp"
#include "drivers/motor/drive_configuration.hpp"
#include "drivers/motor/motor_client.hpp"
#include "drivers/motor/sdo.hpp"

namespace {

ifar::can::Frame frameFrom(const std::uint8_t* data, std::size_t size)
{
  ifar::can::Frame frame;
  if (size < 4) {
    return frame;
  }
  frame.id = (static_cast<std::uint32_t>(data[0]) << 8 | data[1]) & 0x7FF;
  frame.flags = data[2] & 0x07;
  frame.dlc = data[3] % 9;
  for (std::size_t index = 0; index < frame.dlc && 4 + index < size; ++index) {
    frame.data[index] = data[4 + index];
  }
  return frame;
}

// A client that configures its drive first, so SDO answers reach the configurator.
ifar::motor::MotorClientSettings configuringClient()
{
  ifar::motor::MotorClientSettings settings;
  ifar::motor::DriveSetup setup;
  setup.max_velocity = 9066;
  setup.master_heartbeat_timeout_ms = 150;
  setup.rpdo_timeout_ms = 100;
  settings.configuration = ifar::motor::driveConfigurationWrites(setup);
  return settings;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::motor;
  MotorClient client(configuringClient());
  std::int64_t now = 0;
  for (std::size_t offset = 0; offset + 12 <= size; offset += 12) {
    const ifar::can::Frame frame = frameFrom(data + offset, 12);
    const std::uint8_t node = static_cast<std::uint8_t>(frame.id & 0x7F);
    (void)decodeNmt(frame);
    (void)decodeHeartbeat(frame, node);
    (void)decodeEmergency(frame, node);
    (void)decodeSdoAnswer(frame, node);
    if (const auto command = decodeRpdo1(frame, node)) {
      if (!sameContent(encodeRpdo1(node, *command), frame))
        std::abort();
    }
    if (const auto feedback = decodeTpdo1(frame, node)) {
      if (!sameContent(encodeTpdo1(node, *feedback), frame))
        std::abort();
    }
    if (const auto request = decodeSdoRequest(frame, node)) {
      // Reserved bits may differ on the wire; what the request means must survive a round trip.
      if (request->kind == SdoRequest::Kind::kDownload) {
        const auto again = decodeSdoRequest(encodeSdoDownload(node, request->write), node);
        if (!again || !(again->write == request->write))
          std::abort();
      }
    }
    (void)driveStateFromStatusword(static_cast<std::uint16_t>(frame.data[0] | frame.data[1] << 8));
    client.onFrame(frame, now);
    now += 5'000;
    (void)client.update(now);
  }
  return 0;
}
