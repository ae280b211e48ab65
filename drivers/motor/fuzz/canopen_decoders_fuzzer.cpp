// libFuzzer: every CANopen frame decoder, the motor client and the drive emulator fed with arbitrary
// frames must never crash; decoded PDOs must re-encode to the same bytes.
#include <cstdint>
#include <cstdlib>

#include "drivers/motor/canopen_frames.hpp"
#include "drivers/motor/drive_emulator.hpp"
#include "drivers/motor/motor_client.hpp"

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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::motor;
  ifar::motor::MotorClient client;
  ifar::motor::DriveEmulator drive;
  std::int64_t now = 0;
  for (std::size_t offset = 0; offset + 12 <= size; offset += 12) {
    const ifar::can::Frame frame = frameFrom(data + offset, 12);
    const std::uint8_t node = static_cast<std::uint8_t>(frame.id & 0x7F);
    (void)decodeNmt(frame);
    (void)decodeHeartbeat(frame, node);
    (void)decodeEmergency(frame, node);
    if (const auto command = decodeRpdo1(frame, node)) {
      if (!sameContent(encodeRpdo1(node, *command), frame))
        std::abort();
    }
    if (const auto feedback = decodeTpdo1(frame, node)) {
      if (!sameContent(encodeTpdo1(node, *feedback), frame))
        std::abort();
    }
    (void)driveStateFromStatusword(static_cast<std::uint16_t>(frame.data[0] | frame.data[1] << 8));
    client.onFrame(frame, now);
    drive.onFrame(frame, now);
    now += 5'000;
    (void)client.update(now);
    (void)drive.update(now);
  }
  return 0;
}
