#pragma once
// What `ifar launch` starts: a YAML file listing processes, each with its command line, whether it is
// restarted when it dies, and whether the whole launch ends when it ends.
//
//   stop_timeout_s: 3            # after SIGINT, wait this long before SIGKILL
//   readiness_after_s: 5         # the readiness summary this long after start, then on change (0: none)
//   start_wait_s: 15             # longest a process waits for those in its `after` list to be ready
//   processes:
//     - name: sim
//       command: [ifar-sim, demo_room]
//       respawn: true            # restart when it exits or crashes (default false)
//       respawn_delay_s: 0.5     # wait before restarting, doubled per quick crash up to 8 s
//       required: false          # true: when it exits for good, stop everything
//       environment: {SPDLOG_LEVEL: debug}
//       after: [recorder]        # start once these (listed earlier) report ready on their heartbeats
//
// Command arguments and environment values may use ${NAME} and ${NAME:-fallback} (variables.hpp).

#include <map>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "tools/launch/variables.hpp"

namespace ifar::launch {

struct ProcessSpec {
  std::string name;
  std::vector<std::string> command;
  bool respawn = false;
  double respawn_delay_s = 0.5;
  int max_restarts = 100;
  bool required = false;
  std::map<std::string, std::string> environment;
  std::vector<std::string> after;  // processes listed earlier that must be ready before this one starts
};

struct LaunchSpec {
  double stop_timeout_s = 3.0;
  double readiness_after_s = 5.0;  // readiness.hpp; 0 = no summary
  double start_wait_s = 15.0;      // a process waiting on `after` starts anyway after this long
  std::vector<ProcessSpec> processes;
};

/// Reads and validates a launch file (strict: unknown keys, empty commands, duplicate names, unset
/// variables and an `after` naming no earlier process are errors), expanding variables with `lookup`.
LaunchSpec loadLaunchSpec(const common::ConfigNode& root, const VariableLookup& lookup = environmentVariable);

}  // namespace ifar::launch
