#pragma once
// The receive side shared by the buses that queue frames in memory (the in-memory bus, the LCM bridge):
// take the next frame the filters accept, counting it, and let error frames through after updating the
// bus state, as the kernel does for SocketCAN.

#include <deque>
#include <optional>
#include <vector>

#include "drivers/can/can_bus.hpp"

namespace ifar::can {

/// Pops frames from `queue` until one passes `filters` (error frames always pass) and returns it;
/// frames the filters reject are dropped. Empty when the queue runs out.
std::optional<Frame> takeAcceptedFrame(std::deque<Frame>& queue, const std::vector<Filter>& filters,
                                       BusState& state, BusCounters& counters);

}  // namespace ifar::can
