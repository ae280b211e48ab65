// libFuzzer entry: any bytes as a launch file, read as ifar-launch reads one (variables come from a fixed
// table, not the environment). common::ConfigError is the reader's answer to bad input; any other
// exception escapes and fails. A spec that loads starts at least one process, each with a program.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "common/config.hpp"
#include "tools/launch/launch_config.hpp"

namespace {

std::optional<std::string> fixedVariable(const std::string& name)
{
  if (name == "WORLD") {
    return "config/worlds/demo_room.yaml";
  }
  if (name == "EMPTY") {
    return "";
  }
  return std::nullopt;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar;
  launch::LaunchSpec spec;
  try {
    spec = launch::loadLaunchSpec(
        common::ConfigNode::loadString(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml"),
        fixedVariable);
  } catch (const common::ConfigError&) {
    return 0;
  }
  if (spec.processes.empty() || !(spec.stop_timeout_s > 0.0)) {
    std::abort();
  }
  for (const launch::ProcessSpec& process : spec.processes) {
    if (process.name.empty() || process.command.empty() || process.command.front().empty()) {
      std::abort();
    }
  }
  return 0;
}
