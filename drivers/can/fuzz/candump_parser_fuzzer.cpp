// libFuzzer: the candump line parser (and the error-frame decoder behind it) must never crash, and what it
// accepts must format and re-parse to the same frame.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "drivers/can/candump_log.hpp"
#include "drivers/can/error_frame.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const ifar::can::ParsedLine parsed = ifar::can::parseCandumpLine(line);
  if (parsed.status == ifar::can::LineStatus::kOk) {
    // Error frames from a log go through the same state decoding as the kernel's.
    (void)ifar::can::stateAfterErrorFrame(parsed.frame, ifar::can::BusState::kActive);
    (void)ifar::can::describeErrorFrame(parsed.frame);
    const std::string again = ifar::can::formatCandumpLine(parsed.frame, parsed.interface);
    const ifar::can::ParsedLine reparsed = ifar::can::parseCandumpLine(again);
    if (reparsed.status != ifar::can::LineStatus::kOk || !sameContent(reparsed.frame, parsed.frame) ||
        reparsed.frame.timestamp_us != parsed.frame.timestamp_us) {
      std::abort();
    }
  }
  return 0;
}
