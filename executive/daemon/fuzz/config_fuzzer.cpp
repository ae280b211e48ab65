// libFuzzer entry: any bytes as the executive daemon's configuration file, read in the daemon's order:
// common::ConfigNode parses it, the daemon keys (log_level, lcm_url), the obstacles section, then the
// executive's settings, which reject unknown keys. common::ConfigError is the answer to bad input; any
// other exception escapes and fails.

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "common/daemon_main.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/obstacles/local_obstacles.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar;
  try {
    const common::ConfigNode config =
        common::ConfigNode::loadString(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
    common::readDaemonKeys(config);
    executive::loadObstacleSettings(config.child("obstacles"));
    executive::loadExecutiveSettings(config);
  } catch (const common::ConfigError&) {
    return 0;
  }
  return 0;
}
