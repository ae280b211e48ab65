#include "common/daemon_main.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/command_line.hpp"
#include "common/config_search.hpp"
#include "common/logging.hpp"

namespace ifar::common {
namespace {

/// parseLogLevel's complaint about `level`; empty when it is a level.
std::string logLevelProblem(const std::string& level)
{
  try {
    parseLogLevel(level);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return {};
}

/// The common keys and the daemon's own, as YAML that loads as the daemon's config.
std::string effectiveConfig(const DaemonDescription& description, const ConfigNode& config)
{
  const DaemonKeys keys = readDaemonKeys(config);
  std::string text =
      "# ifar-" + description.name + ": effective configuration from " + config.sourceName() + "\n";
  text += daemonKeyParameters().yaml(keys);
  if (description.print_config) {
    text += description.print_config(config);
  }
  return text;
}

/// --print-config: the effective configuration on stdout.
int printConfig(const DaemonDescription& description, const ConfigNode& config)
{
  const std::string text = effectiveConfig(description, config);
  config.rejectUnknownKeys();
  std::cout << text << std::flush;
  return 0;
}

/// One --set KEY=VALUE applied to `config`; ConfigError naming the option when it is not KEY=VALUE.
void applySetting(ConfigNode& config, const std::string& assignment)
{
  const std::size_t equals = assignment.find('=');
  const std::string origin = "--set " + assignment;
  if (equals == std::string::npos) {
    throw ConfigError(origin + ": expected KEY=VALUE, e.g. --set lidar.port=2400");
  }
  config.set(assignment.substr(0, equals), assignment.substr(equals + 1), origin);
}

}  // namespace

const ParameterTable<DaemonKeys>& daemonKeyParameters()
{
  static const auto table =
      ParameterTable<DaemonKeys>()
          .add("log_level", &DaemonKeys::log_level, "", ParameterRange::any(),
               "trace, debug, info, warn, error, critical or off (\"\": SPDLOG_LEVEL or info)")
          .add("lcm_url", &DaemonKeys::lcm_url, "", ParameterRange::any(),
               "LCM URL (\"\": LCM_DEFAULT_URL or LCM's default)");
  return table;
}

DaemonKeys readDaemonKeys(const ConfigNode& config)
{
  DaemonKeys keys;
  daemonKeyParameters().read(config, keys);
  if (!keys.log_level.empty()) {
    if (const std::string problem = logLevelProblem(keys.log_level); !problem.empty()) {
      config.fail("log_level", problem);
    }
  }
  return keys;
}

int runDaemon(int argc, char** argv, const DaemonDescription& description,
              const std::function<int(DaemonContext&)>& body,
              const std::function<void(CLI::App&)>& add_options)
{
  CLI::App app{description.summary, "ifar-" + description.name};
  std::string config_path;  // "" = description.default_config on the configuration search path
  std::string log_level;
  std::string log_directory = "logs";
  std::string lcm_url;
  std::vector<std::string> settings;
  bool print_config = false;
  app.add_option(
      "--config", config_path,
      description.default_config.empty()
          ? std::string("YAML configuration file (default: none)")
          : "YAML configuration file (default: " + description.default_config +
                " from IFAR_CONFIG_DIR, ~/.config/ifar, the install's share/ifar or the checkout; a "
                "relative FILE not found here is looked up there too)");
  app.add_flag("--print-config", print_config,
               "print the effective configuration (YAML, each key's meaning as a comment) and exit");
  app.add_option("--log-level", log_level,
                 "trace, debug, info, warn, error, critical or off (overrides SPDLOG_LEVEL and the config)");
  app.add_option("--log-dir", log_directory, "folder for the rotating log file (\"\" = console only)")
      ->capture_default_str();
  app.add_option("--lcm-url", lcm_url, "LCM URL (overrides the config's lcm_url and LCM_DEFAULT_URL)");
  app.add_option("--set", settings,
                 "set a key of the config as if the file said so, checked like the file's keys; KEY is a "
                 "dotted path, VALUE YAML (repeatable), e.g. --set lidar.port=2400")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  if (add_options) {
    add_options(app);
  }
  if (const auto exit_code = parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  std::shared_ptr<spdlog::logger> logger;
  try {
    std::optional<FoundConfig> found;
    if (!config_path.empty() || !description.default_config.empty()) {
      found = resolveConfigFile(config_path, description.default_config);
    }
    ConfigNode config =
        found ? ConfigNode::loadFile(found->path) : ConfigNode::loadString("", "(no configuration file)");
    for (const std::string& assignment : settings) {
      applySetting(config, assignment);
    }
    if (print_config) {
      return printConfig(description, config);
    }
    // Each source of a level checked on its own, so the message names where a bad one came from (the
    // config's even when another source overrides it: the file stays wrong). The config's lcm_url is read
    // even when --lcm-url overrides it, so the daemon's unknown-key check accepts the key.
    const DaemonKeys keys = readDaemonKeys(config);
    const char* environment_level = std::getenv("SPDLOG_LEVEL");
    for (const auto& [source, level] :
         {std::pair<std::string, std::string>{"--log-level", log_level},
          std::pair<std::string, std::string>{"SPDLOG_LEVEL", environment_level ? environment_level : ""}}) {
      if (!level.empty()) {
        if (const std::string problem = logLevelProblem(level); !problem.empty()) {
          std::string message = source;
          message += ": " + problem;
          throw ConfigError(message);
        }
      }
    }
    LoggingOptions logging;
    logging.log_directory = log_directory;
    logging.config_level = keys.log_level;
    logging.command_line_level = log_level;
    logger = makeLogger(description.name, logging);
    if (found) {
      logger->info("configuration {} ({})", found->path, found->origin);
    }
    DaemonContext context{config, logger, lcm_url.empty() ? keys.lcm_url : lcm_url,
                          [&description, &config] { return effectiveConfig(description, config); }};
    return body(context);
  } catch (const ConfigError& error) {
    std::cerr << "ifar-" << description.name << ": error: " << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    if (logger) {
      logger->critical("stopping on an unexpected error: {}", error.what());
      logger->flush();
    } else {
      std::cerr << "ifar-" << description.name << ": error: " << error.what() << '\n';
    }
    return 1;
  }
}

}  // namespace ifar::common
