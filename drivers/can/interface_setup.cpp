#include "drivers/can/interface_setup.hpp"

namespace ifar::can {

std::vector<CommandLine> interfaceUpCommands(const BusSettings& settings)
{
  return {{"ip", "link", "set", settings.interface, "down"},
          {"ip", "link", "set", settings.interface, "type", "can", "bitrate",
           std::to_string(settings.bitrate), "restart-ms", std::to_string(settings.restart_ms)},
          {"ip", "link", "set", settings.interface, "up"}};
}

std::vector<CommandLine> interfaceDownCommands(const BusSettings& settings)
{
  return {{"ip", "link", "set", settings.interface, "down"}};
}

std::string commandText(const CommandLine& command)
{
  std::string text;
  for (const std::string& word : command) {
    text += (text.empty() ? "" : " ") + word;
  }
  return text;
}

}  // namespace ifar::can
