// ifar replay LOG: publishes a recorded LCM log onto the bus again, on the log's own timing (--speed), read
// with the project's log reader (common/lcm_log): on a corrupt event it stops there, names the byte offset
// and exits 2, instead of crashing or ending as if the log were whole. It never publishes commands unless
// asked for by channel (replay_filter.hpp), says at the start what it leaves out, shows its progress, and
// pauses and resumes: the space bar when standard input is a terminal, SIGUSR1 (pause) and SIGUSR2
// (resume) from anywhere. --gui starts lcm-logplayer-gui on Java 17 instead, with the same channels off.

#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/lcm_log/log_reader.hpp"
#include "common/lcm_log/strict_event_reader.hpp"
#include "common/signals.hpp"
#include "common/time.hpp"
#include "tools/ifar/lcm_java.hpp"
#include "tools/ifar/process.hpp"
#include "tools/replay/log_player_gui.hpp"
#include "tools/replay/playback_clock.hpp"
#include "tools/replay/replay_filter.hpp"
#include "tools/replay/replay_report.hpp"
#include "tools/replay/terminal_keys.hpp"

namespace {

using ifar::lcm_log::LogEvent;
using ifar::lcm_log::LogReader;
using ifar::lcm_log::StrictEventReader;
using ifar::replay::ReplayFilter;
using ifar::replay::TerminalKeys;
using ifar::replay::Verdict;

constexpr int kBadFile = ifar::common::kBadInputExitCode;
constexpr std::int64_t kTerminalProgressUs = 250'000;  // a status line redrawn in place
constexpr std::int64_t kLineProgressUs = 5'000'000;    // one line at a time into a file or a pipe

struct ReplayOptions {
  std::string log;
  double speed = 1.0;
  std::string channels;
  std::string exclude;
  std::vector<std::string> allowed_commands;
  std::string lcm_url;
  bool gui = false;
  bool quiet = false;
  bool start_paused = false;
};

void say(const std::string& line)
{
  std::fprintf(stderr, "ifar replay: %s\n", line.c_str());
}

int fail(int exit_code, const std::string& message)
{
  std::fprintf(stderr, "ifar replay: error: %s\n", message.c_str());
  return exit_code;
}

/// Where and how the log went bad, with the file's name.
std::string corruption(const std::string& path, const StrictEventReader& events)
{
  return "'" + path + "' is corrupt at " + events.problem();
}

sigset_t playerSignals()
{
  sigset_t signals;
  sigemptyset(&signals);
  for (const int signal_number : {SIGINT, SIGTERM, SIGUSR1, SIGUSR2}) {
    sigaddset(&signals, signal_number);
  }
  return signals;
}

/// Plays the log event by event, waiting on a signalfd and the terminal between events.
class Player {
 public:
  Player(LogReader& log, const ReplayFilter& filter, lcm::LCM& bus, const ReplayOptions& options,
         int signal_fd)
      : log_(log), filter_(filter), bus_(bus), options_(options), signal_fd_(signal_fd), clock_(options.speed)
  {
    if (options.start_paused) {
      clock_.pause(ifar::common::monotonicMicroseconds());
    }
    progress_in_place_ = !options.quiet && isatty(STDERR_FILENO) != 0;
  }

  int run()
  {
    if (keys_.active()) {
      say("space pauses and resumes; Ctrl-C stops");
    }
    LogEvent event;
    while (!stopping_ && events_.next(event)) {
      if (!first_log_time_us_) {
        first_log_time_us_ = event.timestamp_us;
      }
      last_log_time_us_ = event.timestamp_us;
      const Verdict verdict = filter_.classify(event.channel, ifar::common::ByteView(event.data));
      if (verdict == Verdict::kPublish) {
        if (!waitUntilDue(event.timestamp_us)) {
          break;
        }
        publish(event);
      }
      report_.count(event.channel, verdict);
      showProgress(false);
    }
    finishProgress();
    if (!events_.problem().empty()) {
      return fail(kBadFile, corruption(options_.log, events_) + "; stopped there. " + report_.summary());
    }
    say((stopping_ ? "stopped: " : "end of log: ") + report_.summary());
    return publish_errors_ == 0 ? 0 : 1;
  }

 private:
  void publish(const LogEvent& event)
  {
    if (bus_.publish(event.channel, event.data.data(), static_cast<unsigned int>(event.data.size())) != 0) {
      ++publish_errors_;
    }
  }

  /// Waits until the event stamped `log_time_us` is due, taking signals and keys meanwhile; false when
  /// asked to stop.
  bool waitUntilDue(std::int64_t log_time_us)
  {
    while (!stopping_) {
      const std::int64_t now = ifar::common::monotonicMicroseconds();
      const std::optional<std::int64_t> wait_us = clock_.waitFor(log_time_us, now);
      if (wait_us && *wait_us == 0) {
        return true;
      }
      std::int64_t timeout_us = wait_us.value_or(kLineProgressUs);
      if (!options_.quiet) {
        timeout_us = std::min(timeout_us, std::max<std::int64_t>(0, next_progress_us_ - now));
      }
      pollfd descriptors[2] = {{signal_fd_, POLLIN, 0}, {TerminalKeys::fileDescriptor(), POLLIN, 0}};
      const int ready =
          poll(descriptors, keys_.active() ? 2 : 1, static_cast<int>((timeout_us + 999) / 1000));
      if (ready > 0) {
        takeSignals();
        while (const std::optional<char> key = keys_.read()) {
          if (*key == ' ') {
            setPaused(!clock_.paused());
          }
        }
      }
      showProgress(false);
    }
    return false;
  }

  void takeSignals()
  {
    signalfd_siginfo info{};
    while (read(signal_fd_, &info, sizeof(info)) == static_cast<ssize_t>(sizeof(info))) {
      const auto signal_number = static_cast<int>(info.ssi_signo);
      if (signal_number == SIGUSR1 || signal_number == SIGUSR2) {
        setPaused(signal_number == SIGUSR1);
      } else {
        stopping_ = true;
      }
    }
  }

  void setPaused(bool paused)
  {
    if (paused == clock_.paused()) {
      return;
    }
    const std::int64_t now = ifar::common::monotonicMicroseconds();
    if (paused) {
      clock_.pause(now);
    } else {
      clock_.resume(now);
    }
    if (line_open_) {
      std::fprintf(stderr, "\r\033[K");  // the status line gives way to the news
      line_open_ = false;
    }
    say(std::string(paused ? "paused" : "resumed") + " at " + progressLine(false));
  }

  std::string progressLine(bool show_paused = true) const
  {
    const std::int64_t elapsed = first_log_time_us_ ? last_log_time_us_ - *first_log_time_us_ : 0;
    return report_.progressLine(elapsed, log_.position(), log_.fileSize(), show_paused && clock_.paused());
  }

  void showProgress(bool force)
  {
    const std::int64_t now = ifar::common::monotonicMicroseconds();
    if (options_.quiet || (!force && now < next_progress_us_)) {
      return;
    }
    next_progress_us_ = now + (progress_in_place_ ? kTerminalProgressUs : kLineProgressUs);
    if (progress_in_place_) {
      std::fprintf(stderr, "\r%s\033[K", progressLine().c_str());
      line_open_ = true;
    } else if (first_log_time_us_) {
      say(progressLine());
    }
  }

  void finishProgress()
  {
    if (line_open_) {
      std::fprintf(stderr, "\r%s\033[K\n", progressLine().c_str());
      line_open_ = false;
    }
  }

  LogReader& log_;
  StrictEventReader events_{log_};
  const ReplayFilter& filter_;
  lcm::LCM& bus_;
  const ReplayOptions& options_;
  int signal_fd_;
  ifar::replay::PlaybackClock clock_;
  ifar::replay::ReplayReport report_;
  TerminalKeys keys_;
  std::optional<std::int64_t> first_log_time_us_;
  std::int64_t last_log_time_us_ = 0;
  std::int64_t next_progress_us_ = 0;
  bool progress_in_place_ = false;
  bool line_open_ = false;
  bool stopping_ = false;
  std::uint64_t publish_errors_ = 0;
};

/// Checks the whole log first (the Java player trusts it) and starts LogPlayer with every channel that
/// holds something `filter` leaves out switched off.
int runGui(const ReplayOptions& options, const ReplayFilter& filter)
{
  LogReader log = LogReader::open(options.log);
  if (!log.openError().empty()) {
    return fail(kBadFile, log.openError());
  }
  std::set<std::string> switched_off;
  StrictEventReader events(log);
  LogEvent event;
  while (events.next(event)) {
    if (filter.classify(event.channel, ifar::common::ByteView(event.data)) != Verdict::kPublish) {
      switched_off.insert(event.channel);
    }
  }
  if (!events.problem().empty()) {
    return fail(kBadFile, corruption(options.log, events) + "; the player is not started on it");
  }
  const std::string jar = ifar::tools::typesJar("");
  if (const std::string problem = ifar::tools::typesJarProblem(jar); !problem.empty()) {
    return fail(1, problem);
  }
  std::string off_list;
  for (const auto& channel : switched_off) {
    off_list += " " + channel;
  }
  say(switched_off.empty() ? std::string("lcm-logplayer-gui: every channel on")
                           : "lcm-logplayer-gui with these channels switched off:" + off_list);
  const std::vector<std::string> arguments = ifar::replay::logPlayerArguments(
      options.log, switched_off, ifar::bus::resolveLcmUrl(options.lcm_url), options.start_paused);
  return fail(
      1, ifar::tools::replaceProcess(ifar::tools::lcmJavaCommand({jar}, "lcm.logging.LogPlayer", arguments)));
}

int runPlayer(const ReplayOptions& options, const ReplayFilter& filter)
{
  LogReader log = LogReader::open(options.log);
  if (!log.openError().empty()) {
    return fail(kBadFile, log.openError());
  }
  // Blocked before LCM starts its threads, so only the signalfd takes them.
  const sigset_t signals = playerSignals();
  ifar::common::restoreDefaultActions(signals);
  sigprocmask(SIG_BLOCK, &signals, nullptr);
  const int signal_fd = signalfd(-1, &signals, SFD_NONBLOCK | SFD_CLOEXEC);
  if (signal_fd < 0) {
    return fail(1, "cannot create a signalfd");
  }
  const std::string url = ifar::bus::resolveLcmUrl(options.lcm_url);
  lcm::LCM bus(url);
  if (!bus.good()) {
    close(signal_fd);
    return fail(1, "cannot start LCM on URL '" + (url.empty() ? std::string("(default)") : url) + "'");
  }
  say("playing " + options.log + " at speed " +
      (options.speed > 0.0 ? std::to_string(options.speed).substr(0, 5)
                           : std::string("0 (as fast as possible)")) +
      (url.empty() ? std::string() : " on " + url) + "; SIGUSR1 pauses, SIGUSR2 resumes");
  say(filter.description());
  const int exit_code = Player(log, filter, bus, options, signal_fd).run();
  close(signal_fd);
  return exit_code;
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Publishes a recorded LCM log onto the bus again, commands left out unless allowed by name. The "
      "commands: VELOCITY_CMD, E_STOP, GOAL, CAN frames to the drives. Stops with the byte offset "
      "and exit code 2 at a corrupt event. Pause and resume: space (on a terminal), SIGUSR1 and SIGUSR2."};
  ReplayOptions options;
  app.add_option("log", options.log, "the .lcmlog file")->required();
  app.add_option("--speed", options.speed, "playback speed multiplier (0 = as fast as possible)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  app.add_option("--channels", options.channels,
                 "regular expression of the channels to play, matching whole names (default: all)");
  app.add_option("--exclude", options.exclude,
                 "regular expression of channels not to play, matching whole names");
  app.add_option(
         "--allow-command", options.allowed_commands,
         "publish the commands on this channel too (VELOCITY_CMD, E_STOP, GOAL, a CAN channel); repeat "
         "for more")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  app.add_flag("--paused", options.start_paused,
               "start paused (space or SIGUSR2 starts playing; with --gui, its play button)");
  app.add_flag("--quiet", options.quiet, "no progress lines");
  app.add_flag(
      "--gui", options.gui,
      "start lcm-logplayer-gui on the log instead (Java 17), with every channel that holds a command "
      "switched off");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  try {
    const ReplayFilter filter(
        options.channels, options.exclude,
        std::set<std::string>(options.allowed_commands.begin(), options.allowed_commands.end()));
    return options.gui ? runGui(options, filter) : runPlayer(options, filter);
  } catch (const std::invalid_argument& error) {
    return fail(ifar::common::kBadInputExitCode, error.what());
  }
}
