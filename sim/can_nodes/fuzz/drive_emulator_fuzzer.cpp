// libFuzzer: the simulated drive fed with arbitrary frames (NMT, RPDO1, SDO requests, heartbeats of the
// node it watches) must never crash, and never demand more than its configured maximum velocity.
#include <cstdint>
#include <cstdlib>

#include "sim/can_nodes/drive_emulator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ifar::sim::DriveEmulator drive;
  std::int64_t now = 0;
  for (std::size_t offset = 0; offset + 12 <= size; offset += 12) {
    ifar::can::Frame frame;
    frame.id = (static_cast<std::uint32_t>(data[offset]) << 8 | data[offset + 1]) & 0x7FF;
    frame.flags = data[offset + 2] & 0x07;
    frame.dlc = data[offset + 3] % 9;
    for (std::size_t index = 0; index < frame.dlc && index < 8; ++index) {
      frame.data[index] = data[offset + 4 + index];
    }
    drive.onFrame(frame, now);
    now += 5'000;
    (void)drive.update(now);
    const std::int64_t limit = drive.objects().max_profile_velocity;
    const std::int64_t demand = drive.velocityDemand();
    if (demand > limit || -demand > limit) {
      std::abort();
    }
  }
  return 0;
}
