#include "common/daemon_main.hpp"

#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <stdexcept>

#include "common/command_line.hpp"
#include "common/logging.hpp"

namespace ifar::common {

int runDaemon(int argc, char** argv, const DaemonDescription& description,
              const std::function<int(DaemonContext&)>& body,
              const std::function<void(CLI::App&)>& add_options)
{
  CLI::App app{description.summary, "ifar-" + description.name};
  std::string config_path = description.default_config;
  std::string log_level;
  std::string log_directory = "logs";
  std::string lcm_url;
  app.add_option("--config", config_path, "YAML configuration file")->capture_default_str();
  app.add_option("--log-level", log_level,
                 "trace, debug, info, warn, error, critical or off (overrides SPDLOG_LEVEL and the config)");
  app.add_option("--log-dir", log_directory, "folder for the rotating log file (\"\" = console only)")
      ->capture_default_str();
  app.add_option("--lcm-url", lcm_url, "LCM URL (overrides the config's lcm_url and LCM_DEFAULT_URL)");
  if (add_options) {
    add_options(app);
  }
  if (const auto exit_code = parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  std::shared_ptr<spdlog::logger> logger;
  try {
    ConfigNode config = config_path.empty() ? ConfigNode::loadString("", "(no configuration file)")
                                            : ConfigNode::loadFile(config_path);
    LoggingOptions logging;
    logging.log_directory = log_directory;
    logging.config_level = config.optional<std::string>("log_level", "");
    logging.command_line_level = log_level;
    // Each source checked on its own, so the message names where the bad level came from (the config's
    // is checked even when another source overrides it: the file stays wrong).
    const char* environment_level = std::getenv("SPDLOG_LEVEL");
    const auto check_level = [](const std::string& level,
                                const std::function<void(const std::string&)>& fail) {
      try {
        parseLogLevel(level);
      } catch (const std::invalid_argument& error) {
        fail(error.what());
      }
    };
    if (!logging.config_level.empty()) {
      check_level(logging.config_level,
                  [&config](const std::string& problem) { config.fail("log_level", problem); });
    }
    if (!log_level.empty()) {
      check_level(log_level,
                  [](const std::string& problem) { throw ConfigError("--log-level: " + problem); });
    }
    if (environment_level != nullptr && *environment_level != '\0') {
      check_level(environment_level,
                  [](const std::string& problem) { throw ConfigError("SPDLOG_LEVEL: " + problem); });
    }
    logger = makeLogger(description.name, logging);
    // Read even when --lcm-url overrides it, so the daemon's unknown-key check accepts the key.
    const std::string configured_url = config.optional<std::string>("lcm_url", "");
    DaemonContext context{config, logger, lcm_url.empty() ? configured_url : lcm_url};
    return body(context);
  } catch (const ConfigError& error) {
    std::cerr << "ifar-" << description.name << ": error: " << error.what() << std::endl;
    return 2;
  } catch (const std::exception& error) {
    if (logger) {
      logger->critical("stopping on an unexpected error: {}", error.what());
      logger->flush();
    } else {
      std::cerr << "ifar-" << description.name << ": error: " << error.what() << std::endl;
    }
    return 1;
  }
}

}  // namespace ifar::common
