#pragma once
// A child process for the multi-process tests: started with posix_spawn, waited for or stopped with a
// signal, and reaped; SIGTERM, then SIGKILL, on destruction if the test did not stop it.

#include <sys/types.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ifar::test_support {

struct ChildOptions {
  std::string output_path;        ///< receives the child's stdout and stderr; empty: inherited
  std::string working_directory;  ///< the child's working directory; empty: this process's
  std::map<std::string, std::string> environment;  ///< set in the child, replacing inherited values
};

class ChildProcess {
 public:
  /// Starts `arguments[0]` (a path) with the rest as its arguments and this process's environment.
  explicit ChildProcess(const std::vector<std::string>& arguments, const ChildOptions& options = {});
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0 || exit_code_.has_value(); }
  /// The process id while it runs, else -1.
  pid_t pid() const { return pid_; }
  /// Waits up to `seconds` for the child to exit: its exit code (-1 when killed by a signal), or nothing
  /// while it still runs.
  std::optional<int> waitFor(double seconds);
  /// Sends `signal_number` and waits up to 5 s: the exit code, or -1 when the child did not exit
  /// normally in time (it is then killed).
  int stop(int signal_number);

 private:
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
};

/// Runs a program to its end (at most `timeout_s`, then it is killed): its exit code, -1 when it could not
/// start, was killed or timed out.
int runToEnd(const std::vector<std::string>& arguments, const ChildOptions& options, double timeout_s);

/// The whole text of a file (a child's output, a log), "" when it cannot be read.
std::string readText(const std::string& path);

}  // namespace ifar::test_support
