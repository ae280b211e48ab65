#include "drivers/can/can_bus.hpp"

namespace ifar::can {

const char* toString(BusState state)
{
  switch (state) {
    case BusState::kActive:
      return "error-active";
    case BusState::kWarning:
      return "error-warning";
    case BusState::kPassive:
      return "error-passive";
    case BusState::kBusOff:
      return "bus-off";
  }
  return "unknown";
}

const char* toString(IoStatus status)
{
  switch (status) {
    case IoStatus::kOk:
      return "ok";
    case IoStatus::kTimeout:
      return "timeout";
    case IoStatus::kEndOfStream:
      return "end of stream";
    case IoStatus::kError:
      return "error";
  }
  return "unknown";
}

bool accepts(const std::vector<Filter>& filters, const Frame& frame)
{
  if (filters.empty() || frame.error()) {
    return true;
  }
  for (const Filter& filter : filters) {
    if (filter.extended == frame.extended() && (frame.id & filter.mask) == (filter.id & filter.mask)) {
      return true;
    }
  }
  return false;
}

}  // namespace ifar::can
