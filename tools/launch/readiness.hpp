#pragma once
// What `ifar launch` says about start-up: which processes are up and healthy. Each process's line comes
// from the supervisor (running, restarting, ended, with its last output line) and from its heartbeat_t on
// HEARTBEAT, matched by pid (every daemon and the recorder beat once a second; a driver's message names
// what it waits for, "no lidar packets from 192.168.1.201:2368 for 5.0 s"). The summary is printed once a
// few seconds after start and then whenever a line changes, the clock in its durations aside. No LCM here:
// ifar-launch feeds the heartbeats in.

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ifar::launch {

/// One process of the launch as the supervisor sees it.
struct ProcessState {
  std::string name;
  pid_t pid = -1;               // -1 while not running
  std::int64_t started_us = 0;  // monotonic, of the current (or last) start
  int restarts = 0;
  bool restart_pending = false;  // it exited and will be started again
  bool done = false;             // it exited and will not be
  std::string last_exit;         // "exited with code 1", "" before the first exit
  std::string exit_output;       // its last line of output before that exit, for why it exited
  std::string waiting_for;       // not started yet: the processes it waits for, "recorder, sim"
};

/// The parts of a heartbeat_t the summary uses.
struct Heartbeat {
  std::int32_t pid = 0;
  std::string process;
  std::int8_t health = 0;  // heartbeat_t::HEALTH_OK, HEALTH_DEGRADED or HEALTH_ERROR
  std::string message;
};

struct ReadinessSettings {
  double first_report_s = 5.0;       // the first summary this long after start; 0: never
  double heartbeat_timeout_s = 3.0;  // a running process without a beat this long has no heartbeat
};

class Readiness {
 public:
  Readiness(ReadinessSettings settings, std::int64_t start_us);

  /// A heartbeat received at `now_us` (monotonic).
  void onHeartbeat(const Heartbeat& beat, std::int64_t now_us);

  /// The summary lines when one is due (the first after first_report_s, then on any change), else nullopt.
  std::optional<std::vector<std::string>> report(const std::vector<ProcessState>& processes,
                                                 std::int64_t now_us);

  /// Whether `process` runs and its latest heartbeat since its start, a recent one, says OK.
  bool ready(const ProcessState& process, std::int64_t now_us) const;

  /// The summary as it stands: a header "readiness after 5 s: 4 of 6 ready", then one line per process.
  std::vector<std::string> summary(const std::vector<ProcessState>& processes, std::int64_t now_us) const;

 private:
  struct Beat {
    Heartbeat heartbeat;
    std::int64_t received_us = 0;
  };
  /// "ready", "not ready: MESSAGE", "error: MESSAGE", "starting", "up, no heartbeat", "restarting: ...".
  std::string stateOf(const ProcessState& process, std::int64_t now_us, bool& ready) const;

  ReadinessSettings settings_;
  std::int64_t start_us_;
  std::map<std::int32_t, Beat> beats_;  // by pid
  bool reported_ = false;
  std::vector<std::string> last_;  // the last report, durations aside
};

}  // namespace ifar::launch
