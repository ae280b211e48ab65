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

const common::ParameterTable<BusSettings>& busParameters()
{
  using S = BusSettings;
  using Range = common::ParameterRange;
  static const auto table =
      common::ParameterTable<S>()
          .choice(
              "kind", &S::kind,
              {{"socketcan", BusKind::kSocketCan}, {"lcm", BusKind::kLcm}, {"candump", BusKind::kCandump}},
              "socketcan: a vehicle's bus; lcm: the bridge (can_frame_t on lcm_channel); candump: replay a "
              "log")
          .required()
          .add("interface", &S::interface, "", Range::any(), "socketcan: the interface")
          .add("bitrate", &S::bitrate, "bit/s", Range::between(10000, 1000000),
               "socketcan: the bus bit rate, set by `ifar can up` (the ifar-can systemd unit) when it brings "
               "the interface up; the drives and the force sensor use the same")
          .add("restart_ms", &S::restart_ms, "ms", Range::between(0, 60000),
               "socketcan: the kernel restarts a bus-off controller after this long (ifar can up); 0 = it "
               "stays off until brought up again")
          .add("lcm_channel", &S::lcm_channel, "", Range::any(),
               "lcm: channel carrying the bus as can_frame_t")
          .add("candump_input", &S::candump_input, "", Range::any(),
               "candump: log to replay (candump -l format)")
          .add("candump_output", &S::candump_output, "", Range::any(),
               "candump: log to append sent frames to");
  return table;
}

const common::ParameterTable<BusChannels>& busChannelParameters()
{
  using S = BusChannels;
  using Range = common::ParameterRange;
  static const auto table =
      common::ParameterTable<S>()
          .add("raw_channel", &S::raw_channel, "", Range::any(),
               "where a socketcan/candump daemon republishes received frames (can_frame_t)")
          .add("status_channel", &S::status_channel, "", Range::any(), "can_bus_status_t, once a second");
  return table;
}

BusSettings loadBusSettings(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("bus");
  BusSettings settings;
  busParameters().read(node, settings);
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
