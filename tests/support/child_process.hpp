#pragma once
// A child process for the multi-process replay tests: started with posix_spawn, stopped with a signal
// and reaped; SIGTERM, then SIGKILL, on destruction if the test did not stop it.

#include <sys/types.h>

#include <string>
#include <vector>

namespace ifar::replay_testing {

class ChildProcess {
 public:
  /// Starts `arguments[0]` (a path) with the rest as its arguments; the environment is inherited.
  /// `output_path`, when not empty, receives the child's stdout and stderr; `working_directory`, when not
  /// empty, is the child's working directory (this process's stays as it is).
  explicit ChildProcess(const std::vector<std::string>& arguments, const std::string& output_path = "",
                        const std::string& working_directory = "");
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }
  /// Sends `signal_number` and waits up to 5 s: the exit code, or -1 when the child did not exit
  /// normally in time (it is then killed).
  int stop(int signal_number);

 private:
  pid_t pid_ = -1;
};

}  // namespace ifar::replay_testing
