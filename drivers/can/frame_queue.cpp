#include "drivers/can/frame_queue.hpp"

#include "drivers/can/error_frame.hpp"

namespace ifar::can {

std::optional<Frame> takeAcceptedFrame(std::deque<Frame>& queue, const std::vector<Filter>& filters,
                                       BusState& state, BusCounters& counters)
{
  while (!queue.empty()) {
    const Frame frame = queue.front();
    queue.pop_front();
    if (frame.error()) {
      ++counters.error_frames;
      if (const auto next = stateAfterErrorFrame(frame, state)) {
        state = *next;
      }
      return frame;
    }
    if (accepts(filters, frame)) {
      ++counters.frames_received;
      return frame;
    }
  }
  return std::nullopt;
}

}  // namespace ifar::can
