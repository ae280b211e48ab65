// libFuzzer: the force frame decoder and the monitor fed with arbitrary frames must never crash, and a
// decoded frame must re-encode to the same bytes.
#include <cstdint>
#include <cstdlib>

#include "drivers/force_sensor/force_frame.hpp"
#include "drivers/force_sensor/force_monitor.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ifar::force_sensor::ForceMonitor monitor;
  std::int64_t now = 0;
  for (std::size_t offset = 0; offset + 11 <= size; offset += 11) {
    ifar::can::Frame frame;
    frame.id = (static_cast<std::uint32_t>(data[offset]) << 8 | data[offset + 1]) & 0x7FF;
    frame.flags = static_cast<std::uint8_t>(data[offset + 2] & 0x07);
    frame.dlc = static_cast<std::uint8_t>(data[offset + 2] >> 4) % 9;
    for (std::size_t index = 0; index < frame.dlc; ++index) {
      frame.data[index] = data[offset + 3 + index];
    }
    const auto decoded = ifar::force_sensor::decodeForceFrame(frame);
    if (decoded.status == ifar::force_sensor::DecodeStatus::kOk) {
      const auto again = ifar::force_sensor::encodeForceFrame(decoded.reading);
      // Reserved byte 6 is not kept by the decoder; everything else must match.
      if (again.id != frame.id || again.dlc != frame.dlc || again.data[0] != frame.data[0] ||
          again.data[3] != frame.data[3] || again.data[5] != frame.data[5] ||
          (again.data[4] & 0x03) != (frame.data[4] & 0x03)) {
        std::abort();
      }
    }
    (void)monitor.onFrame(frame, now);
    (void)monitor.sample(now);
    now += static_cast<std::int64_t>(data[offset + 2]) * 1000;
  }
  return 0;
}
