// ifar record: lcm-logger into logs/ with a timestamped name, split every 512 MB, recording the channels of
// --channels only; and a heartbeat for the recorder. `ifar record` runs lcm-logger as its child, subscribes
// to the same channels itself, and publishes heartbeat_t "recorder" on HEARTBEAT once a second: DEGRADED
// until lcm-logger has written its first message (ifar launch starts the rest then), OK while lcm-logger
// runs and its file grows as messages arrive, ERROR (at once, with the reason) when it has
// died or its file has not grown for --stall-seconds while messages arrived. When lcm-logger dies
// `ifar record` exits 1, so `ifar launch` restarts both.

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "bus/heartbeat.hpp"
#include "bus/lcm_url.hpp"
#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/time.hpp"
#include "ifar/heartbeat_t.hpp"
#include "tools/ifar/process.hpp"
#include "tools/record/logger_command.hpp"
#include "tools/record/logger_process.hpp"
#include "tools/record/recorder_watch.hpp"

namespace {

constexpr const char* kProcessName = "recorder";
constexpr double kWatchPeriodS = 0.1;
constexpr double kHeartbeatPeriodS = 1.0;
constexpr double kLoggerStopTimeoutS = 5.0;
constexpr int kLcmDefaultQueueMessages = 30;  // what LCM gives a subscription that asks for nothing

struct RecordOptions {
  std::string directory = "logs";
  std::string name_pattern = "ifar-%Y-%m-%d-%H%M%S.lcmlog";
  double split_mb = 512.0;
  int rotate = 0;
  std::string channels = ".*";
  std::string lcm_url;
  double stall_seconds = 3.0;
  double receive_buffer_mb =
      static_cast<double>(ifar::bus::kReceiveBufferBytes) / (1024.0 * 1024.0);  // as every daemon's
  // LCM's queue between lcm-logger's receiving thread and its main thread: about three seconds of the
  // stack's bus (1,600 messages a second, most of them lidar packets of 1.2 kB, so about 6 MB when full),
  // enough for the backlog a driver publishes at once after it was kept off the CPU.
  int queue_messages = 5000;
};

int fail(const std::string& message)
{
  std::fprintf(stderr, "ifar record: error: %s\n", message.c_str());
  return 1;
}

/// The library that sets lcm-logger's queue (tools/record/logger_queue_preload.cpp), where the build and
/// the install put it relative to this program.
std::string loggerQueueLibrary()
{
  return (std::filesystem::path(ifar::tools::executableDirectory()) / IFAR_LOGGER_QUEUE_FROM_BIN)
      .lexically_normal()
      .string();
}

/// What lcm-logger runs with over the recorder's environment, and the queue LCM gives it then.
struct LoggerEnvironment {
  std::vector<std::string> variables;  // "NAME=VALUE"
  int queue_messages = kLcmDefaultQueueMessages;
};

/// lcm-logger's LCM URL, and the preload that gives its subscription `queue_messages` of queue (none for
/// 0, LCM's own 30). Says on standard error when the library is missing.
LoggerEnvironment loggerEnvironment(const std::string& url, int queue_messages)
{
  LoggerEnvironment environment;
  if (!url.empty()) {
    environment.variables.push_back("LCM_DEFAULT_URL=" + url);
  }
  if (queue_messages == 0) {
    return environment;
  }
  const std::string library = loggerQueueLibrary();
  if (access(library.c_str(), R_OK) != 0) {
    std::fprintf(stderr,
                 "ifar record: warning: %s is missing: lcm-logger keeps LCM's queue of %d messages and loses "
                 "what arrives in a burst beyond it\n",
                 library.c_str(), kLcmDefaultQueueMessages);
    return environment;
  }
  const char* preloaded = std::getenv("LD_PRELOAD");
  environment.variables.push_back(
      "LD_PRELOAD=" + library +
      (preloaded != nullptr && *preloaded != '\0' ? ":" + std::string(preloaded) : ""));
  environment.variables.push_back("IFAR_LOGGER_QUEUE_MESSAGES=" + std::to_string(queue_messages));
  environment.queue_messages = queue_messages;
  return environment;
}

/// Watches lcm-logger from the run loop and publishes the recorder's heartbeats.
class Recorder {
 public:
  Recorder(ifar::bus::RunLoop& loop, ifar::record::LoggerProcess& logger, const RecordOptions& options)
      : loop_(loop), logger_(logger), watch_(ifar::common::secondsToMicroseconds(options.stall_seconds))
  {
    beat_.process = kProcessName;
    beat_.pid = static_cast<std::int32_t>(getpid());
    loop.subscribeRaw(options.channels, [this](const lcm::ReceiveBuffer*, const std::string& /*channel*/) {
      watch_.onMessage(ifar::common::monotonicMicroseconds());
    });
    loop.every(kWatchPeriodS, [this] { look(); });
    loop.every(kHeartbeatPeriodS, [this] { beat(); });
  }

  /// 1 when lcm-logger died on its own, 0 when the recorder was asked to stop.
  int exitCode() const { return logger_died_ ? 1 : 0; }

  /// Passes on what lcm-logger wrote (to standard error) and notes each file it opened.
  void passOnLoggerOutput()
  {
    for (const std::string& line : logger_.readLines()) {
      std::fprintf(stderr, "%s\n", line.c_str());
      if (const std::optional<std::string> file = ifar::record::openedLogFile(line)) {
        watch_.onLogFile(*file, ifar::common::monotonicMicroseconds());
      }
    }
  }

 private:
  void look()
  {
    passOnLoggerOutput();
    const std::int64_t now = ifar::common::monotonicMicroseconds();
    if (!watch_.logFile().empty()) {
      std::error_code error;
      const std::uintmax_t size = std::filesystem::file_size(watch_.logFile(), error);
      watch_.onFileSize(error ? std::nullopt : std::optional<std::uint64_t>(size), now);
    }
    // On SIGINT to the process group lcm-logger stops with the recorder: no alarm for that.
    if (loop_.stopping()) {
      return;
    }
    if (const std::optional<std::string> exit = logger_.pollExit()) {
      passOnLoggerOutput();  // its last words, written just before it ended
      watch_.onLoggerExit(*exit);
      logger_died_ = true;
      beat();
      loop_.stop();
      return;
    }
    // A change of health is reported at once, not at the next beat; until lcm-logger records, each look
    // sends a beat, the message whose appearance in the file shows it does.
    const std::int8_t level = watch_.health(now).level;
    if (level != beat_.health || level == ifar::heartbeat_t::HEALTH_DEGRADED) {
      beat();
    }
  }

  void beat()
  {
    const ifar::record::RecorderHealth health = watch_.health(ifar::common::monotonicMicroseconds());
    if (health.level != beat_.health || health.message != beat_.message) {
      std::fprintf(stderr, "ifar record: %s\n",
                   health.message.empty() ? "recording" : health.message.c_str());
    }
    beat_.utime = ifar::common::nowMicroseconds();
    beat_.health = health.level;
    beat_.message = health.message;
    loop_.publish(ifar::bus::kHeartbeatChannel, beat_);
    ++beat_.sequence;
  }

  ifar::bus::RunLoop& loop_;
  ifar::record::LoggerProcess& logger_;
  ifar::record::RecorderWatch watch_;
  ifar::heartbeat_t beat_{};
  bool logger_died_ = false;
};

int record(const RecordOptions& options)
{
  std::error_code error;
  std::filesystem::create_directories(options.directory, error);
  if (error) {
    return fail("cannot create the log folder '" + options.directory + "': " + error.message());
  }
  const std::string url = ifar::bus::withReceiveBuffer(
      ifar::bus::resolveLcmUrl(options.lcm_url), std::lround(options.receive_buffer_mb * 1024.0 * 1024.0));
  ifar::record::LoggerRequest request;
  request.file_pattern = (std::filesystem::path(options.directory) / options.name_pattern).string();
  request.channels = options.channels;
  request.split_mb = options.split_mb;
  request.rotate = options.rotate;
  // The run loop first: it blocks SIGINT/SIGTERM before LCM's threads start; lcm-logger unblocks them.
  ifar::bus::RunLoop loop(url, spdlog::stderr_logger_mt("record"));
  const LoggerEnvironment environment = loggerEnvironment(url, options.queue_messages);
  ifar::record::LoggerProcess logger(ifar::record::loggerArguments(request), environment.variables);
  if (!logger.startError().empty()) {
    return fail(logger.startError() + " (install liblcm-bin; scripts/setup does)");
  }
  Recorder recorder(loop, logger, options);
  std::fprintf(
      stderr,
      "ifar record: logging channels '%s' on %s to %s (%s, queue of %d messages); heartbeat \"%s\" on "
      "HEARTBEAT; stop with Ctrl-C\n",
      options.channels.c_str(), url.empty() ? "LCM's default URL" : url.c_str(), request.file_pattern.c_str(),
      options.rotate > 0 ? ("rotating " + std::to_string(options.rotate) + " files").c_str() : "numbered",
      environment.queue_messages, kProcessName);
  loop.run();
  if (recorder.exitCode() == 0) {
    const std::string how = logger.stop(kLoggerStopTimeoutS);
    recorder.passOnLoggerOutput();
    std::fprintf(stderr, "ifar record: lcm-logger %s\n", how.c_str());
  }
  return recorder.exitCode();
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Records LCM channels with lcm-logger into logs/, watched by a heartbeat \"recorder\". Timestamped "
      "names, split every 512 MB; the heartbeat on HEARTBEAT is ERROR when lcm-logger dies or its file "
      "stops growing while messages arrive"};
  RecordOptions options;
  app.add_option("--dir", options.directory, "folder for the logs")->capture_default_str();
  app.add_option("--name", options.name_pattern, "file name, strftime-formatted")->capture_default_str();
  app.add_option("--split-mb", options.split_mb, "start a new numbered file after this many MB (0 = never)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  app.add_option("--rotate", options.rotate,
                 "keep only this many files, newest as NAME.0 (0 = number them instead)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  app.add_option("--channels", options.channels, "regular expression of the channels to record (whole names)")
      ->capture_default_str();
  app.add_option("--stall-seconds", options.stall_seconds,
                 "health ERROR when the log file has not grown for this long while messages arrived")
      ->check(ifar::common::atLeast(0.2))
      ->capture_default_str();
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  app.add_option("--receive-buffer-mb", options.receive_buffer_mb,
                 "kernel receive buffer lcm-logger asks for on a udpm:// URL without recv_buf_size (0 = the "
                 "system's default; net.core.rmem_max caps it, and LCM says so)")
      ->check(ifar::common::atLeast(0.0))
      ->capture_default_str();
  app.add_option("--queue-messages", options.queue_messages,
                 "messages LCM holds for lcm-logger while its main thread is busy (LCM drops what comes "
                 "beyond; 0 = LCM's own 30, which a burst of lidar packets overflows)")
      ->check(CLI::Range(0, 10'000'000))
      ->capture_default_str();
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  try {
    return record(options);
  } catch (const std::exception& error) {
    return fail(error.what());
  }
}
