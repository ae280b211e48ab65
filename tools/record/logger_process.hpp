#pragma once
// lcm-logger as a child of `ifar record`: its stop signals at their defaults and unblocked whatever the
// parent blocks, in the parent's process group (so Ctrl-C and `ifar launch`'s stop reach both), stopped
// when the parent dies, and its output (standard output and error) on a pipe the parent reads: it names
// each file it opens there, and the parent passes every line on. Its environment is the parent's with the
// variables given to it set (the recorder's preload of a longer LCM queue, record_main.cpp).

#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace ifar::record {

class LoggerProcess {
 public:
  /// Starts `arguments` (the program found on PATH) with `environment` ("NAME=VALUE" each) set over the
  /// parent's environment; check startError().
  explicit LoggerProcess(const std::vector<std::string>& arguments,
                         const std::vector<std::string>& environment = {});
  /// Kills and reaps the process when it still runs.
  ~LoggerProcess();
  LoggerProcess(const LoggerProcess&) = delete;
  LoggerProcess& operator=(const LoggerProcess&) = delete;

  const std::string& startError() const { return start_error_; }
  pid_t pid() const { return pid_; }
  /// The pipe's read end, to poll (non-blocking).
  int errorOutput() const { return error_output_; }

  /// The whole lines it has written since the last call, without their newlines.
  std::vector<std::string> readLines();
  /// How it ended ("exited with code 0", "killed by signal 9 (Killed)") once it has; nothing while it runs.
  std::optional<std::string> pollExit();
  /// SIGINT, then SIGKILL after `timeout_s`; returns how it ended.
  std::string stop(double timeout_s);

 private:
  pid_t pid_ = -1;
  int error_output_ = -1;
  std::string start_error_;
  std::string partial_line_;
  std::optional<std::string> exit_;
};

/// `base` ("NAME=VALUE" each, as `environ`) with every variable of `changes` set: replaced where `base` has
/// it, added at the end where not.
std::vector<std::string> environmentWith(const std::vector<std::string>& base,
                                         const std::vector<std::string>& changes);

/// The log file named by one of lcm-logger's lines, `Opening log file "PATH"`; nothing for other lines.
std::optional<std::string> openedLogFile(const std::string& line);

}  // namespace ifar::record
