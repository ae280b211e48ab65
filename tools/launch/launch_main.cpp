// ifar launch CONFIG: starts the processes a launch file lists (simulator or not, drivers, planner,
// executive, logger), prefixes their output with their names, restarts those marked respawn, and stops
// them all cleanly on Ctrl-C. It listens to HEARTBEAT on LCM (LCM_DEFAULT_URL, as its processes do) and
// prints a readiness summary a few seconds after start and on every change (tools/launch/readiness.hpp).

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/config_search.hpp"
#include "common/time.hpp"
#include "ifar/heartbeat_t.hpp"
#include "lcmtypes/checked_decode.hpp"
#include "tools/launch/launch_config.hpp"
#include "tools/launch/supervisor.hpp"

namespace {

/// Heartbeats from LCM into `readiness`; the summary announced through `supervisor` when one is due.
class ReadinessWatch {
 public:
  /// Joins LCM when there is a summary to print or a process to start when others are ready.
  ReadinessWatch(double first_report_s, bool starts_wait, ifar::launch::Supervisor& supervisor)
      : readiness_({first_report_s, 3.0}, ifar::common::monotonicMicroseconds()), supervisor_(supervisor)
  {
    if (first_report_s <= 0.0 && !starts_wait) {
      return;
    }
    const std::string url = ifar::bus::resolveLcmUrl("");
    lcm_ = std::make_unique<lcm::LCM>(url);
    if (!lcm_->good()) {
      supervisor_.announce("readiness: cannot join LCM at '" + url + "': heartbeats are not watched");
      lcm_.reset();
      return;
    }
    lcm_->subscribe(ifar::bus::kHeartbeatChannel, &ReadinessWatch::onMessage, this);
  }

  /// Whether `process` is ready by its heartbeat; without LCM nothing can be, so waiting ones start after
  /// the launch file's start wait.
  bool ready(const ifar::launch::ProcessState& process) const
  {
    return readiness_.ready(process, ifar::common::monotonicMicroseconds());
  }

  /// Each turn of the supervisor's loop: what has arrived, then the summary if it is due.
  void turn()
  {
    if (lcm_) {
      // Everything pending: on the default URL every message of the stack arrives here, not only beats.
      for (int handled = 0; handled < 10000 && lcm_->handleTimeout(0) > 0; ++handled) {
      }
    }
    if (const auto lines =
            readiness_.report(supervisor_.processStates(), ifar::common::monotonicMicroseconds())) {
      for (const std::string& line : *lines) {
        supervisor_.announce(line);
      }
    }
  }

 private:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/)
  {
    ifar::heartbeat_t beat;
    if (!ifar::lcmtypes::decodeLcm(beat, buffer->data, buffer->data_size).ok()) {
      return;  // not a heartbeat: nothing to say about readiness
    }
    readiness_.onHeartbeat({beat.pid, beat.process, beat.health, beat.message},
                           ifar::common::monotonicMicroseconds());
  }

  ifar::launch::Readiness readiness_;
  ifar::launch::Supervisor& supervisor_;
  std::unique_ptr<lcm::LCM> lcm_;
};

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Starts the processes of a launch file with respawn, prefixed output and clean shutdown"};
  std::string config_path;
  double duration_s = 0.0;
  bool no_colour = false;
  app.add_option("config", config_path,
                 "launch file, or its name in launch/ on the configuration search path (vehicle, sim_demo)")
      ->required();
  app.add_option("--duration", duration_s, "stop everything after this many seconds (0 = run until Ctrl-C)")
      ->check(ifar::common::atLeast(0));
  app.add_flag("--no-colour", no_colour, "plain output even on a terminal");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  ifar::launch::LaunchSpec spec;
  try {
    const auto found = ifar::common::findNamedInput(config_path, "launch");
    if (!found) {
      throw ifar::common::ConfigError(config_path + ": no such launch file here, nor launch/" + config_path +
                                      "[.yaml] on the configuration search path");
    }
    std::cout << "ifar launch: " << found->path << " (" << found->origin << ")\n" << std::flush;
    spec = ifar::launch::loadLaunchSpec(ifar::common::ConfigNode::loadFile(found->path));
  } catch (const ifar::common::ConfigError& error) {
    std::cerr << "ifar-launch: error: " << error.what() << '\n';
    return 2;
  }
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::string program_directory = error ? std::string(".") : self.parent_path().string();
  // A closed stdout (ifar launch ... | head) must not end the launch and orphan its processes: they are
  // still stopped in order.
  signal(SIGPIPE, SIG_IGN);
  const double readiness_after_s = spec.readiness_after_s;
  const bool starts_wait = std::any_of(spec.processes.begin(), spec.processes.end(),
                                       [](const auto& process) { return !process.after.empty(); });
  ifar::launch::Supervisor supervisor(std::move(spec), program_directory, std::cout,
                                      !no_colour && isatty(STDOUT_FILENO) != 0);
  ReadinessWatch readiness(readiness_after_s, starts_wait, supervisor);
  const auto result = supervisor.run(
      duration_s, [&readiness] { readiness.turn(); },
      [&readiness](const ifar::launch::ProcessState& process) { return readiness.ready(process); });
  return result.exit_code;
}
