#include "drivers/can/open_bus.hpp"

#include "drivers/can/candump_log.hpp"
#include "drivers/can/lcm_bridge_bus.hpp"
#include "drivers/can/socketcan_bus.hpp"

namespace ifar::can {

const char* toString(BusKind kind)
{
  switch (kind) {
    case BusKind::kSocketCan:
      return "socketcan";
    case BusKind::kLcm:
      return "lcm";
    case BusKind::kCandump:
      return "candump";
  }
  return "unknown";
}

BusSettings loadBusSettings(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("bus");
  BusSettings settings;
  const auto kind = node.required<std::string>("kind");
  if (kind == "socketcan") {
    settings.kind = BusKind::kSocketCan;
  } else if (kind == "lcm") {
    settings.kind = BusKind::kLcm;
  } else if (kind == "candump") {
    settings.kind = BusKind::kCandump;
  } else {
    node.fail("kind", "'" + kind + "' is not one of socketcan, lcm, candump");
  }
  settings.interface = node.optional<std::string>("interface", settings.interface);
  settings.lcm_channel = node.optional<std::string>("lcm_channel", settings.lcm_channel);
  settings.candump_input = node.optional<std::string>("candump_input", "");
  settings.candump_output = node.optional<std::string>("candump_output", "");
  if (settings.kind == BusKind::kCandump && settings.candump_input.empty() &&
      settings.candump_output.empty()) {
    node.fail("candump_input", "kind candump needs candump_input or candump_output");
  }
  return settings;
}

OpenBusResult openBus(const BusSettings& settings, lcm::LCM& lcm)
{
  OpenBusResult result;
  switch (settings.kind) {
    case BusKind::kSocketCan: {
      auto opened = SocketCanBus::open(settings.interface);
      result.bus = std::move(opened.bus);
      result.error = std::move(opened.error);
      break;
    }
    case BusKind::kLcm:
      result.bus = std::make_unique<LcmBridgeBus>(lcm, settings.lcm_channel);
      break;
    case BusKind::kCandump: {
      auto opened = CandumpLogBus::open(settings.candump_input, settings.candump_output);
      result.bus = std::move(opened.bus);
      result.error = std::move(opened.error);
      break;
    }
  }
  return result;
}

}  // namespace ifar::can
