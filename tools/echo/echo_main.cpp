// ifar echo CHANNEL: prints the messages on CHANNEL (a regular expression matching whole channel names, as
// LCM takes it), live from the bus or from a log (--log), decoded as text or as JSON lines (--json). Any
// project type is decoded, found by the fingerprint each message starts with; what is not a project type or
// does not decode is counted and skipped, never trusted. A log is read with the project's reader: at a
// corrupt event it stops, names the byte offset and exits 2.

#include <cstdio>
#include <memory>
#include <regex>
#include <string>
#include <variant>

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/lcm_log/log_reader.hpp"
#include "common/lcm_log/strict_event_reader.hpp"
#include "common/time.hpp"
#include "lcmtypes/message_schema.hpp"
#include "tools/echo/message_format.hpp"
#include "tools/echo/message_value.hpp"

namespace {

using ifar::echo::Members;
using ifar::echo::MessageOrigin;

struct EchoOptions {
  std::string channel;
  std::string log;
  std::string lcm_url;
  bool json = false;
  std::int64_t count = 0;  // 0: no limit
};

int fail(int exit_code, const std::string& message)
{
  std::fprintf(stderr, "ifar echo: error: %s\n", message.c_str());
  return exit_code;
}

/// Decodes and prints messages, and counts what it shows and skips.
class Echo {
 public:
  explicit Echo(const EchoOptions& options) : options_(options), types_(ifar::lcmtypes::messageSchema()) {}

  /// Prints one message; false once --count messages have been shown.
  bool show(const std::string& channel, ifar::common::ByteView bytes, std::int64_t receive_utime)
  {
    if (channel == "LCM_SELF_TEST") {
      return true;  // LCM's own udpm loopback probe
    }
    const ifar::lcm_wire::StructType* type = types_.typeOf(bytes);
    if (type == nullptr) {
      skip(channel, "not a project type (unknown fingerprint)");
      return true;
    }
    std::variant<Members, std::string> decoded = types_.decode(*type, bytes);
    if (const auto* problem = std::get_if<std::string>(&decoded)) {
      skip(channel, "does not decode: " + *problem);
      return true;
    }
    const MessageOrigin origin{channel, type->name, receive_utime};
    const Members& members = std::get<Members>(decoded);
    const std::string text =
        options_.json ? ifar::echo::jsonLine(origin, members) + "\n" : ifar::echo::textBlock(origin, members);
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    ++shown_;
    return options_.count == 0 || shown_ < options_.count;
  }

  /// A closing line on stderr when anything was skipped.
  void reportSkipped() const
  {
    if (skipped_ > 0) {
      std::fprintf(stderr, "ifar echo: %lld messages shown, %lld skipped\n", static_cast<long long>(shown_),
                   static_cast<long long>(skipped_));
    }
  }

 private:
  void skip(const std::string& channel, const std::string& why)
  {
    ++skipped_;
    // One line a second at most: a stream of bad messages must not flood the terminal.
    const std::int64_t now = ifar::common::monotonicMicroseconds();
    if (now - last_warning_us_ >= 1'000'000) {
      last_warning_us_ = now;
      std::fprintf(stderr, "ifar echo: skipping a message on %s: %s (%lld skipped so far)\n", channel.c_str(),
                   why.c_str(), static_cast<long long>(skipped_));
    }
  }

  const EchoOptions& options_;
  ifar::echo::MessageTypes types_;
  std::int64_t shown_ = 0;
  std::int64_t skipped_ = 0;
  std::int64_t last_warning_us_ = -1'000'000'000;
};

int echoLog(const EchoOptions& options, const std::regex& channel)
{
  ifar::lcm_log::LogReader log = ifar::lcm_log::LogReader::open(options.log);
  if (!log.openError().empty()) {
    return fail(ifar::common::kBadInputExitCode, log.openError());
  }
  Echo echo(options);
  ifar::lcm_log::StrictEventReader events(log);
  ifar::lcm_log::LogEvent event;
  bool more = true;
  while (more && events.next(event)) {
    if (std::regex_match(event.channel, channel)) {
      more = echo.show(event.channel, ifar::common::ByteView(event.data), event.timestamp_us);
    }
  }
  echo.reportSkipped();
  if (more && !events.problem().empty()) {
    return fail(ifar::common::kBadInputExitCode, "'" + options.log + "' is corrupt at " + events.problem());
  }
  return 0;
}

int echoBus(const EchoOptions& options)
{
  auto logger = spdlog::stderr_logger_mt("echo");
  ifar::bus::RunLoop loop(options.lcm_url, logger);
  Echo echo(options);
  loop.subscribeRaw(
      options.channel, [&loop, &echo](const lcm::ReceiveBuffer* buffer, const std::string& channel) {
        const ifar::common::ByteView bytes(static_cast<const std::uint8_t*>(buffer->data), buffer->data_size);
        if (!echo.show(channel, bytes, buffer->recv_utime)) {
          loop.stop();
        }
      });
  const int exit_code = loop.run();
  echo.reportSkipped();
  return exit_code;
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Prints the messages on a channel decoded as text or JSON lines, live from LCM or from a log. Any "
      "project type, found by the message's fingerprint; what does not decode is counted and skipped."};
  EchoOptions options;
  app.add_option("channel", options.channel, "channel name, or a regular expression matching whole names")
      ->required();
  app.add_flag("--json", options.json, "one JSON object per message and line instead of text");
  app.add_option("--log", options.log, "read this .lcmlog file instead of the bus");
  app.add_option("--count", options.count, "stop after this many messages (0 = no limit)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  std::regex channel;
  try {
    channel = std::regex(options.channel, std::regex::ECMAScript);
  } catch (const std::regex_error& error) {
    return fail(ifar::common::kBadInputExitCode,
                "channel '" + options.channel + "' is not a regular expression: " + error.what());
  }
  if (!options.log.empty()) {
    return echoLog(options, channel);
  }
  try {
    return echoBus(options);
  } catch (const std::exception& error) {
    return fail(1, error.what());
  }
}
