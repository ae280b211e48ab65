#pragma once
// The start-up every daemon shares: --help, --config FILE, --log-level LEVEL, --lcm-url URL,
// --set KEY=VALUE (repeatable: a key of the config replaced before the daemon reads it, so it is checked
// like the file's own; a launch file gives each stack its own ports this way, e.g. --set lidar.port=23781),
// --print-config (the effective configuration as YAML with each key's meaning, then exit 0); the config
// loaded strictly; the named logger made; bad config reported as "error: <file>: key '<k>': ..." (or
// "error: --set <k>=<v>: key '<k>': ..." for a --set one) and exit code 2; any escaping exception logged and
// exit code 1.
//
//   int main(int argc, char** argv) {
//     return ifar::common::runDaemon(argc, argv, {"planner", "DV-graph planner", "planner.yaml"},
//                                    [](ifar::common::DaemonContext& context) {
//                                      const auto settings = loadPlannerSettings(context.config);
//                                      context.config.rejectUnknownKeys();
//                                      ... return exit code ...
//                                    });
//   }
//
// The YAML may hold `log_level: info` and `lcm_url: udpm://...` at top level; runDaemon reads both.

#include <functional>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "common/config.hpp"
#include "common/parameters.hpp"

namespace ifar::common {

struct DaemonDescription {
  std::string name;            // logger and process name, e.g. "planner"
  std::string summary;         // one line for --help
  std::string default_config;  // name on the configuration search path (config_search.hpp); "" = none
  /// For --print-config: loads the daemon's settings from its config (with every check the daemon makes)
  /// and returns them as YAML (ParameterTable::dump); log_level and lcm_url are added before it. Empty:
  /// only those two.
  std::function<std::string(const ConfigNode& config)> print_config;
};

struct DaemonContext {
  ConfigNode config;
  std::shared_ptr<spdlog::logger> logger;
  std::string lcm_url;  // from --lcm-url, else the config's lcm_url, else "" (LCM_DEFAULT_URL / default)
  /// What --print-config prints: YAML that loads as this configuration (for the daemon's journal).
  std::function<std::string()> effective_config;
};

/// The settings every daemon's config may hold at its top level; "" when not set.
struct DaemonKeys {
  std::string log_level;
  std::string lcm_url;
};

/// The keys every daemon's config may hold at its top level.
const ParameterTable<DaemonKeys>& daemonKeyParameters();

/// Reads log_level and lcm_url (so the daemon's unknown-key check accepts them); throws ConfigError naming
/// the file and the key for a log level that is not one. The headless runner reads the daemons' files
/// with it too.
DaemonKeys readDaemonKeys(const ConfigNode& config);

/// `add_options` may register extra command-line options before parsing (may be empty).
int runDaemon(int argc, char** argv, const DaemonDescription& description,
              const std::function<int(DaemonContext&)>& body,
              const std::function<void(CLI::App&)>& add_options = {});

}  // namespace ifar::common
