// libFuzzer: arbitrary bytes on a CAN_* LCM channel: LCM's decoder, then our can_frame_t -> Frame
// conversion must never crash, and a frame it accepts must convert back to the same message content.
#include <cstdint>
#include <cstdlib>

#include "drivers/can/lcm_bridge_bus.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ifar::can_frame_t message;
  if (message.decode(data, 0, static_cast<int>(size)) < 0) {
    return 0;
  }
  bool valid = false;
  const ifar::can::Frame frame = ifar::can::fromLcm(message, &valid);
  if (valid) {
    const ifar::can_frame_t back = ifar::can::toLcm(frame);
    if (back.id != message.id || back.flags != message.flags || back.dlc != message.dlc) {
      std::abort();
    }
    for (int index = 0; index < message.dlc; ++index) {
      if (back.data[index] != message.data[index])
        std::abort();
    }
  }
  return 0;
}
