#pragma once
// One named spdlog logger per daemon: console plus a rotating file logs/<name>.log.
// Level precedence: --log-level (LoggingOptions::command_line_level) > SPDLOG_LEVEL > config > info.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <spdlog/spdlog.h>

namespace ifar::common {

struct LoggingOptions {
  std::string log_directory = "logs";  // created if missing; "" disables the file sink
  std::string config_level;            // from the daemon's YAML ("" = not set)
  std::string command_line_level;      // from --log-level ("" = not set)
  std::size_t max_file_bytes = 10 * 1024 * 1024;
  std::size_t max_files = 5;
};

/// Parses "trace", "debug", "info", "warn", "error", "critical", "off". Throws std::invalid_argument.
spdlog::level::level_enum parseLogLevel(const std::string& text);

/// The level the precedence rule picks, given the SPDLOG_LEVEL value (nullptr when unset).
spdlog::level::level_enum chooseLogLevel(const LoggingOptions& options, const char* environment_level);

/// `text` with newlines, carriage returns and tabs written as \n, \r, \t and every other control character
/// as \xNN: one log line stays one line whatever a message from the bus holds.
std::string escapeControlCharacters(std::string_view text);

/// The daemons' log line: time, logger name, level and the message with its control characters escaped.
std::unique_ptr<spdlog::formatter> daemonLogFormatter();

/// Creates (or replaces) and registers the logger `name` with console and rotating-file sinks, each line
/// written by daemonLogFormatter().
std::shared_ptr<spdlog::logger> makeLogger(const std::string& name, const LoggingOptions& options);

}  // namespace ifar::common
