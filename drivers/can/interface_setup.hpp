#pragma once
// Bringing a SocketCAN interface up at the configured bit rate (ifar can up, run by the ifar-can systemd
// unit at boot) and down again: the `ip link` commands that do it, from can.yaml's bus section. The bit rate
// can only change while the interface is down, so up takes it down first.

#include <string>
#include <vector>

#include "drivers/can/open_bus.hpp"

namespace ifar::can {

using CommandLine = std::vector<std::string>;

/// ip link set IF down; ip link set IF type can bitrate B restart-ms R; ip link set IF up.
std::vector<CommandLine> interfaceUpCommands(const BusSettings& settings);

/// ip link set IF down.
std::vector<CommandLine> interfaceDownCommands(const BusSettings& settings);

/// "ip link set can0 up": a command as a person would type it.
std::string commandText(const CommandLine& command);

}  // namespace ifar::can
