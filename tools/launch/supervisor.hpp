#pragma once
// Runs the processes of a launch file: starts each in its own process group with its output prefixed by
// its name (one with an `after` list once those are ready, or after the start wait), restarts the ones marked
// respawn when they die (with back-off), and on SIGINT/SIGTERM, when a required process ends, or after a set
// duration, stops them all: SIGINT first, SIGKILL after the timeout.

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "tools/launch/launch_config.hpp"
#include "tools/launch/readiness.hpp"

namespace ifar::launch {

struct SupervisorResult {
  int exit_code = 0;   // 0: stopped on request or after the duration; 1: a required process failed
  int restarts = 0;    // respawns over the whole run
  std::string reason;  // why the launch ended
};

class Supervisor {
 public:
  /// `program_directory` is put first on PATH so ifar-* executables beside `ifar` are found.
  Supervisor(LaunchSpec spec, std::string program_directory, std::ostream& out, bool colour);
  ~Supervisor();
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  /// Whether a running process is ready (from its heartbeat: readiness.hpp).
  using ReadyCheck = std::function<bool(const ProcessState&)>;

  /// Runs until a signal, a required process ending, or `duration_s` (<= 0: no limit). `each_turn` (may be
  /// empty) is called on every turn of the loop, at least every 50 ms, while the processes run. A process
  /// with an `after` list starts when `is_ready` says each of those is (empty: at once).
  SupervisorResult run(double duration_s, const std::function<void()>& each_turn = {},
                       const ReadyCheck& is_ready = {});

  /// Every process of the launch file, in its order, as it is now.
  std::vector<ProcessState> processStates() const;

  /// A line of the launch's own ("launch | ..."), between the processes' output.
  void announce(const std::string& line) { say("launch", line); }

 private:
  struct Child {
    ProcessSpec spec;
    pid_t pid = -1;
    int output_fd = -1;
    std::string partial_line;
    int restarts = 0;
    double delay_s = 0.0;
    std::int64_t started_us = 0;
    std::int64_t restart_due_us = -1;  // when a respawn is scheduled
    bool done = false;                 // exited and will not be restarted
    std::string last_output;           // its last line of output
    std::string last_exit;             // how it ended last, "" before it has
    std::string exit_output;           // last_output when it did
    bool waiting = false;              // not started yet: waits for its `after` list
  };

  void start(Child& child);
  /// Starts each waiting process whose `after` list is ready, has ended, or has been waited on too long.
  void startWaiting(const ReadyCheck& is_ready, std::int64_t run_started_us);
  ProcessState stateOf(const Child& child) const;
  void reapChildren(bool stopping, SupervisorResult& result);
  void drainOutput(Child& child, bool flush_partial);
  void say(const std::string& name, const std::string& line);
  void stopAll(double timeout_s);

  std::vector<Child> children_;
  std::string program_directory_;
  std::ostream& out_;
  bool colour_;
  double stop_timeout_s_;
  double start_wait_s_;
  int signal_fd_ = -1;
  std::size_t name_width_ = 0;
};

}  // namespace ifar::launch
