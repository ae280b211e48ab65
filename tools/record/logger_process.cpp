#include "tools/record/logger_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "common/signals.hpp"
#include "common/time.hpp"
#include "tools/ifar/process.hpp"

namespace ifar::record {

std::vector<std::string> environmentWith(const std::vector<std::string>& base,
                                         const std::vector<std::string>& changes)
{
  std::vector<std::string> result = base;
  for (const std::string& change : changes) {
    const std::string name = change.substr(0, change.find('=') + 1);  // with its '='
    const auto same = std::find_if(result.begin(), result.end(), [&name](const std::string& variable) {
      return variable.compare(0, name.size(), name) == 0;
    });
    if (same != result.end()) {
      *same = change;
    } else {
      result.push_back(change);
    }
  }
  return result;
}

LoggerProcess::LoggerProcess(const std::vector<std::string>& arguments,
                             const std::vector<std::string>& environment)
{
  const std::string program = tools::findProgram(arguments.front());
  if (program.empty()) {
    start_error_ = arguments.front() + " is not installed (not found on PATH)";
    return;
  }
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    start_error_ = std::string("cannot create a pipe: ") + std::strerror(errno);
    return;
  }
  // Everything the child needs is prepared before fork: between fork and exec it only makes
  // async-signal-safe calls (LCM's threads may hold locks the child would wait on for ever).
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const auto& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));  // execv's signature predates const
  }
  argv.push_back(nullptr);
  std::vector<std::string> parent_environment;
  for (char** variable = environ; *variable != nullptr; ++variable) {
    parent_environment.emplace_back(*variable);
  }
  const std::vector<std::string> child_environment = environmentWith(parent_environment, environment);
  std::vector<char*> envp;
  envp.reserve(child_environment.size() + 1);
  for (const auto& variable : child_environment) {
    envp.push_back(const_cast<char*>(variable.c_str()));  // execve's signature predates const
  }
  envp.push_back(nullptr);
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    sigaddset(&stop_signals, signal_number);
  }
  sigset_t none;
  sigemptyset(&none);
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ == 0) {
    common::restoreDefaultActions(stop_signals);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    // A recorder killed outright takes its logger with it (SIGINT: lcm-logger closes its file cleanly)
    // instead of leaving it to run beside the recorder started in its place.
    prctl(PR_SET_PDEATHSIG, SIGINT);
    if (getppid() != parent || dup2(pipe_fds[1], STDOUT_FILENO) < 0 || dup2(pipe_fds[1], STDERR_FILENO) < 0) {
      _exit(127);
    }
    execve(program.c_str(), argv.data(), envp.data());
    _exit(127);
  }
  const int fork_error = errno;
  close(pipe_fds[1]);
  if (pid_ < 0) {
    close(pipe_fds[0]);
    start_error_ = "cannot start " + arguments.front() + ": " + std::strerror(fork_error);
    return;
  }
  error_output_ = pipe_fds[0];
  fcntl(error_output_, F_SETFL, fcntl(error_output_, F_GETFL) | O_NONBLOCK);
}

LoggerProcess::~LoggerProcess()
{
  if (pid_ > 0 && !exit_) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (error_output_ >= 0) {
    close(error_output_);
  }
}

std::vector<std::string> LoggerProcess::readLines()
{
  std::vector<std::string> lines;
  char buffer[4096];
  ssize_t got = 0;
  while (error_output_ >= 0 && (got = read(error_output_, buffer, sizeof(buffer))) > 0) {
    partial_line_.append(buffer, static_cast<std::size_t>(got));
  }
  std::size_t end = 0;
  while ((end = partial_line_.find('\n')) != std::string::npos) {
    lines.push_back(partial_line_.substr(0, end));
    partial_line_.erase(0, end + 1);
  }
  return lines;
}

std::optional<std::string> LoggerProcess::pollExit()
{
  if (exit_ || pid_ <= 0) {
    return exit_;
  }
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    exit_ = tools::describeExitStatus(status);
  }
  return exit_;
}

std::string LoggerProcess::stop(double timeout_s)
{
  if (pid_ <= 0) {
    return start_error_;
  }
  if (!pollExit()) {
    kill(pid_, SIGINT);
  }
  const std::int64_t deadline = common::monotonicMicroseconds() + common::secondsToMicroseconds(timeout_s);
  while (!pollExit() && common::monotonicMicroseconds() < deadline) {
    usleep(10'000);
  }
  if (!exit_) {
    kill(pid_, SIGKILL);
    int status = 0;
    waitpid(pid_, &status, 0);
    exit_ = tools::describeExitStatus(status);
  }
  return *exit_;
}

std::optional<std::string> openedLogFile(const std::string& line)
{
  const std::string prefix = "Opening log file \"";
  if (line.rfind(prefix, 0) != 0 || line.size() < prefix.size() + 2 || line.back() != '"') {
    return std::nullopt;
  }
  return line.substr(prefix.size(), line.size() - prefix.size() - 1);
}

}  // namespace ifar::record
