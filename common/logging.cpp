#include "common/logging.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/rotating_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace ifar::common {
namespace {

/// The message with every control character written as an escape: text from the bus (an E_STOP reason,
/// a heartbeat's message) cannot start a forged log line or move the terminal's cursor.
class EscapedMessage : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg& message, const std::tm& /*time*/,
              spdlog::memory_buf_t& out) override
  {
    const std::string escaped =
        escapeControlCharacters(std::string_view(message.payload.data(), message.payload.size()));
    out.append(escaped.data(), escaped.data() + escaped.size());
  }
  std::unique_ptr<spdlog::custom_flag_formatter> clone() const override
  {
    return std::make_unique<EscapedMessage>();
  }
};

}  // namespace

std::string escapeControlCharacters(std::string_view text)
{
  std::string escaped;
  escaped.reserve(text.size());
  for (const char character : text) {
    const auto byte = static_cast<unsigned char>(character);
    if (character == '\n') {
      escaped += "\\n";
    } else if (character == '\r') {
      escaped += "\\r";
    } else if (character == '\t') {
      escaped += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      escaped += "\\x";
      escaped += kHex[byte >> 4];
      escaped += kHex[byte & 0xf];
    } else {
      escaped += character;
    }
  }
  return escaped;
}

std::unique_ptr<spdlog::formatter> daemonLogFormatter()
{
  auto formatter = std::make_unique<spdlog::pattern_formatter>();
  formatter->add_flag<EscapedMessage>('*').set_pattern("%Y-%m-%d %H:%M:%S.%e [%n] [%^%l%$] %*");
  return formatter;
}

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
  logger->set_formatter(daemonLogFormatter());
  logger->flush_on(spdlog::level::warn);
  spdlog::drop(name);
  spdlog::register_logger(logger);
  return logger;
}

}  // namespace ifar::common
