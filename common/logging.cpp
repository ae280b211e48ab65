#include "common/logging.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <spdlog/sinks/rotating_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace ifar::common {

spdlog::level::level_enum parseLogLevel(const std::string& text)
{
  static const std::pair<const char*, spdlog::level::level_enum> kLevels[] = {
      {"trace", spdlog::level::trace},       {"debug", spdlog::level::debug},  {"info", spdlog::level::info},
      {"warn", spdlog::level::warn},         {"warning", spdlog::level::warn}, {"error", spdlog::level::err},
      {"critical", spdlog::level::critical}, {"off", spdlog::level::off}};
  for (const auto& [name, level] : kLevels) {
    if (text == name) {
      return level;
    }
  }
  throw std::invalid_argument("unknown log level '" + text +
                              "' (expected trace, debug, info, warn, error, critical or off)");
}

spdlog::level::level_enum chooseLogLevel(const LoggingOptions& options, const char* environment_level)
{
  if (!options.command_line_level.empty()) {
    return parseLogLevel(options.command_line_level);
  }
  if (environment_level != nullptr && *environment_level != '\0') {
    return parseLogLevel(environment_level);
  }
  if (!options.config_level.empty()) {
    return parseLogLevel(options.config_level);
  }
  return spdlog::level::info;
}

std::shared_ptr<spdlog::logger> makeLogger(const std::string& name, const LoggingOptions& options)
{
  std::vector<spdlog::sink_ptr> sinks;
  sinks.push_back(std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  if (!options.log_directory.empty()) {
    std::filesystem::create_directories(options.log_directory);
    const auto file = (std::filesystem::path(options.log_directory) / (name + ".log")).string();
    sinks.push_back(std::make_shared<spdlog::sinks::rotating_file_sink_mt>(file, options.max_file_bytes,
                                                                           options.max_files));
  }
  auto logger = std::make_shared<spdlog::logger>(name, sinks.begin(), sinks.end());
  logger->set_level(chooseLogLevel(options, std::getenv("SPDLOG_LEVEL")));
  logger->set_pattern("%Y-%m-%d %H:%M:%S.%e [%n] [%^%l%$] %v");
  logger->flush_on(spdlog::level::warn);
  spdlog::drop(name);
  spdlog::register_logger(logger);
  return logger;
}

}  // namespace ifar::common
