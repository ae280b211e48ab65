#include "tools/launch/supervisor.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "common/signals.hpp"
#include "common/time.hpp"
#include "tools/ifar/process.hpp"

namespace ifar::launch {
namespace {

constexpr double kMaxRespawnDelayS = 8.0;
constexpr double kStableRunS = 10.0;  // a process up this long resets its back-off

sigset_t handledSignals()
{
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGCHLD);
  return signals;
}

const char* colourOf(std::size_t index)
{
  static const char* kColours[] = {"\033[36m", "\033[33m", "\033[35m", "\033[32m", "\033[34m", "\033[91m"};
  return kColours[index % (sizeof(kColours) / sizeof(kColours[0]))];
}

}  // namespace

Supervisor::Supervisor(LaunchSpec spec, std::string program_directory, std::ostream& out, bool colour)
    : program_directory_(std::move(program_directory)),
      out_(out),
      colour_(colour),
      stop_timeout_s_(spec.stop_timeout_s),
      start_wait_s_(spec.start_wait_s)
{
  for (auto& process : spec.processes) {
    name_width_ = std::max(name_width_, process.name.size());
    Child child;
    child.delay_s = process.respawn_delay_s;
    child.spec = std::move(process);
    children_.push_back(std::move(child));
  }
  name_width_ = std::max<std::size_t>(name_width_, 6);
  const sigset_t signals = handledSignals();
  common::restoreDefaultActions(signals);
  sigprocmask(SIG_BLOCK, &signals, nullptr);
  signal_fd_ = signalfd(-1, &signals, SFD_NONBLOCK | SFD_CLOEXEC);
  if (signal_fd_ < 0) {
    throw std::runtime_error("cannot create a signalfd");
  }
}

Supervisor::~Supervisor()
{
  stopAll(stop_timeout_s_);
  if (signal_fd_ >= 0) {
    close(signal_fd_);
  }
}

void Supervisor::say(const std::string& name, const std::string& line)
{
  std::string padded = name;
  padded.resize(name_width_, ' ');
  std::size_t index = 0;
  for (std::size_t candidate = 0; candidate < children_.size(); ++candidate) {
    if (children_[candidate].spec.name == name) {
      index = candidate;
    }
  }
  if (colour_ && name != "launch") {
    out_ << colourOf(index) << padded << " |\033[0m " << line << '\n';
  } else {
    out_ << padded << " | " << line << '\n';
  }
  out_.flush();
}

void Supervisor::start(Child& child)
{
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    say("launch", "cannot create a pipe for " + child.spec.name + ": " + std::strerror(errno));
    child.done = true;
    return;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    say("launch", "cannot fork " + child.spec.name + ": " + std::strerror(errno));
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    child.done = true;
    return;
  }
  if (pid == 0) {
    // In the child: own process group (so stopping reaches its children), default signals, output to
    // the pipe, then the program.
    setpgid(0, 0);
    const sigset_t signals = handledSignals();
    common::restoreDefaultActions(signals);
    sigprocmask(SIG_UNBLOCK, &signals, nullptr);
    signal(SIGPIPE, SIG_DFL);  // the launch itself ignores it
    dup2(pipe_fds[1], STDOUT_FILENO);
    dup2(pipe_fds[1], STDERR_FILENO);
    const char* path = std::getenv("PATH");
    const std::string new_path = program_directory_ + ":" + (path != nullptr ? path : "/usr/bin:/bin");
    setenv("PATH", new_path.c_str(), 1);
    for (const auto& [key, value] : child.spec.environment) {
      setenv(key.c_str(), value.c_str(), 1);
    }
    std::vector<char*> argv;
    argv.reserve(child.spec.command.size() + 1);
    for (const auto& argument : child.spec.command) {
      argv.push_back(const_cast<char*>(argument.c_str()));  // execvp predates const
    }
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    const std::string message =
        "cannot run '" + child.spec.command.front() + "': " + std::strerror(errno) + "\n";
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, message.data(), message.size());
    _exit(127);
  }
  setpgid(pid, pid);  // also from the parent, so the group exists before any signal is sent
  close(pipe_fds[1]);
  fcntl(pipe_fds[0], F_SETFL, O_NONBLOCK);
  child.pid = pid;
  child.output_fd = pipe_fds[0];
  child.started_us = common::monotonicMicroseconds();
  child.restart_due_us = -1;
  std::string command;
  for (const auto& argument : child.spec.command) {
    command += (command.empty() ? "" : " ") + argument;
  }
  say("launch", "started " + child.spec.name + " (pid " + std::to_string(pid) + "): " + command);
}

void Supervisor::drainOutput(Child& child, bool flush_partial)
{
  if (child.output_fd < 0) {
    return;
  }
  char buffer[4096];
  while (true) {
    const ssize_t count = read(child.output_fd, buffer, sizeof(buffer));
    if (count <= 0) {
      if (count == 0 || (errno != EAGAIN && errno != EINTR)) {
        flush_partial = true;
        close(child.output_fd);
        child.output_fd = -1;
      }
      break;
    }
    child.partial_line.append(buffer, static_cast<std::size_t>(count));
    std::size_t newline;
    while ((newline = child.partial_line.find('\n')) != std::string::npos) {
      say(child.spec.name, child.partial_line.substr(0, newline));
      if (newline > 0) {
        child.last_output = child.partial_line.substr(0, newline);
      }
      child.partial_line.erase(0, newline + 1);
    }
  }
  if (flush_partial && !child.partial_line.empty()) {
    say(child.spec.name, child.partial_line);
    child.last_output = child.partial_line;
    child.partial_line.clear();
  }
}

void Supervisor::reapChildren(bool stopping, SupervisorResult& result)
{
  int status = 0;
  pid_t pid;
  while ((pid = waitpid(-1, &status, WNOHANG)) > 0) {
    for (auto& child : children_) {
      if (child.pid != pid) {
        continue;
      }
      drainOutput(child, true);
      child.pid = -1;
      child.last_exit = tools::describeExitStatus(status);
      child.exit_output = child.last_output;
      say("launch", child.spec.name + " " + child.last_exit);
      if (stopping) {
        child.done = true;
        break;
      }
      const std::int64_t now = common::monotonicMicroseconds();
      if (child.spec.respawn && child.restarts < child.spec.max_restarts) {
        // Back off when it keeps crashing right after start.
        if (common::microsecondsToSeconds(now - child.started_us) > kStableRunS) {
          child.delay_s = child.spec.respawn_delay_s;
        }
        child.restart_due_us = now + common::secondsToMicroseconds(child.delay_s);
        say("launch",
            "restarting " + child.spec.name + " in " + std::to_string(child.delay_s).substr(0, 4) + " s");
        child.delay_s = std::min(kMaxRespawnDelayS, child.delay_s * 2.0);
      } else {
        child.done = true;
        if (child.spec.required) {
          const bool failed = !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
          result.reason = "required process " + child.spec.name + " " + tools::describeExitStatus(status);
          result.exit_code = failed ? 1 : 0;
        }
      }
      break;
    }
  }
}

namespace {
/// How long the first process of the file (the recorder) is left running after the others have stopped.
constexpr double kRecorderCatchUpS = 0.5;
}  // namespace

void Supervisor::stopAll(double timeout_s)
{
  // In the reverse of the file's order, each one gone (or killed) before the next is asked: what starts
  // first (the recorder) stops last, so the log holds everyone's last messages (the executive's arrival,
  // its zero velocity on shutdown).
  SupervisorResult ignored;
  // Passes on everyone's output and reaps until `child` is gone or `seconds` have passed.
  const auto waitWhileRunning = [&](const Child& child, double seconds) {
    const std::int64_t until = common::monotonicMicroseconds() + common::secondsToMicroseconds(seconds);
    while (child.pid > 0 && common::monotonicMicroseconds() < until) {
      for (auto& other : children_) {
        drainOutput(other, false);
      }
      reapChildren(true, ignored);
      usleep(10'000);
    }
  };
  for (auto child = children_.rbegin(); child != children_.rend(); ++child) {
    if (child->pid <= 0) {
      continue;
    }
    if (child + 1 == children_.rend() && children_.size() > 1) {
      // The first one (the recorder) may still have the others' last messages in its socket: lcm-logger
      // stops on SIGINT without reading them, so it gets a moment to catch up on a busy machine.
      waitWhileRunning(*child, kRecorderCatchUpS);
      if (child->pid <= 0) {
        continue;
      }
    }
    kill(-child->pid, SIGINT);
    waitWhileRunning(*child, timeout_s);
    if (child->pid > 0) {
      say("launch", child->spec.name + " did not stop within " + std::to_string(timeout_s).substr(0, 4) +
                        " s: killing it");
      kill(-child->pid, SIGKILL);
      while (child->pid > 0) {
        reapChildren(true, ignored);
        usleep(10'000);
      }
    }
  }
}

ProcessState Supervisor::stateOf(const Child& child) const
{
  ProcessState state;
  state.name = child.spec.name;
  state.pid = child.pid;
  state.started_us = child.started_us;
  state.restarts = child.restarts;
  state.restart_pending = child.pid < 0 && !child.done && child.restart_due_us >= 0;
  state.done = child.done;
  state.last_exit = child.last_exit;
  state.exit_output = child.exit_output;
  if (child.waiting) {
    for (const std::string& name : child.spec.after) {
      state.waiting_for += (state.waiting_for.empty() ? "" : ", ") + name;
    }
  }
  return state;
}

std::vector<ProcessState> Supervisor::processStates() const
{
  std::vector<ProcessState> states;
  states.reserve(children_.size());
  for (const Child& child : children_) {
    states.push_back(stateOf(child));
  }
  return states;
}

void Supervisor::startWaiting(const ReadyCheck& is_ready, std::int64_t run_started_us)
{
  const std::int64_t now = common::monotonicMicroseconds();
  const bool waited_too_long = now - run_started_us >= common::secondsToMicroseconds(start_wait_s_);
  for (Child& child : children_) {
    if (!child.waiting) {
      continue;
    }
    std::string not_ready;
    bool ended = false;
    for (const std::string& name : child.spec.after) {
      const auto found = std::find_if(children_.begin(), children_.end(),
                                      [&name](const Child& other) { return other.spec.name == name; });
      if (found == children_.end()) {
        continue;  // the launch file's loader refuses that; nothing to wait for
      }
      ended = ended || found->done;
      if (!found->done && !(is_ready && is_ready(stateOf(*found)))) {
        not_ready += (not_ready.empty() ? "" : ", ") + name;
      }
    }
    if (!not_ready.empty() && !waited_too_long) {
      continue;
    }
    child.waiting = false;
    if (!not_ready.empty()) {
      say("launch", "starting " + child.spec.name + " after waiting " +
                        std::to_string(start_wait_s_).substr(0, 4) + " s; not ready: " + not_ready);
    } else if (ended) {
      say("launch", "starting " + child.spec.name + ": a process it waited for has ended");
    }
    start(child);
  }
}

SupervisorResult Supervisor::run(double duration_s, const std::function<void()>& each_turn,
                                 const ReadyCheck& is_ready)
{
  SupervisorResult result;
  const std::int64_t run_started_us = common::monotonicMicroseconds();
  for (auto& child : children_) {
    if (child.spec.after.empty() || !is_ready) {
      start(child);
      continue;
    }
    // What starts before the recorder is recording is lost from the log (the first pose, the first
    // scan), and a log missing a node's first inputs cannot be replayed to the same outputs.
    child.waiting = true;
    say("launch", child.spec.name + " starts when ready: " + stateOf(child).waiting_for);
  }
  const std::int64_t end_us =
      duration_s > 0.0 ? common::monotonicMicroseconds() + common::secondsToMicroseconds(duration_s) : -1;
  while (result.reason.empty()) {
    std::vector<pollfd> descriptors{{signal_fd_, POLLIN, 0}};
    for (const auto& child : children_) {
      if (child.output_fd >= 0) {
        descriptors.push_back({child.output_fd, POLLIN, 0});
      }
    }
    poll(descriptors.data(), descriptors.size(), 50);
    signalfd_siginfo info{};
    while (read(signal_fd_, &info, sizeof(info)) == static_cast<ssize_t>(sizeof(info))) {
      if (info.ssi_signo == SIGINT || info.ssi_signo == SIGTERM) {
        result.reason = std::string("received ") + strsignal(static_cast<int>(info.ssi_signo));
      }
    }
    for (auto& child : children_) {
      drainOutput(child, false);
    }
    reapChildren(false, result);
    const std::int64_t now = common::monotonicMicroseconds();
    for (auto& child : children_) {
      if (!child.done && child.pid < 0 && child.restart_due_us >= 0 && now >= child.restart_due_us) {
        ++child.restarts;
        ++result.restarts;
        start(child);
      }
    }
    if (each_turn && result.reason.empty()) {
      each_turn();
    }
    if (result.reason.empty()) {
      startWaiting(is_ready, run_started_us);
    }
    if (end_us >= 0 && now >= end_us && result.reason.empty()) {
      result.reason = "ran for the requested " + std::to_string(duration_s).substr(0, 5) + " s";
    }
    const bool all_done =
        std::all_of(children_.begin(), children_.end(), [](const Child& child) { return child.done; });
    if (all_done && result.reason.empty()) {
      result.reason = "every process ended";
    }
  }
  say("launch", "stopping: " + result.reason);
  stopAll(stop_timeout_s_);
  say("launch", "stopped (" + std::to_string(result.restarts) + " restarts)");
  return result;
}

}  // namespace ifar::launch
