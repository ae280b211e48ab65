// ifar goal X,Y: sends a navigation goal on GOAL (a few times, so a lossy link or a late subscriber still
// gets it; the planner treats repeats of one goal_id as one goal). With --wait it keeps resending the goal
// once a second (a respawned planner learns it again) and watches EXEC_STATUS until the executive reports
// the goal reached (exit 0) or the wait runs out (exit 1): the demo and the system tests end on this.

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include <spdlog/sinks/null_sink.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/time.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/goal_t.hpp"

namespace {

const char* modeName(std::int8_t mode)
{
  switch (mode) {
    case ifar::exec_status_t::MODE_IDLE:
      return "idle";
    case ifar::exec_status_t::MODE_FOLLOW:
      return "follow";
    case ifar::exec_status_t::MODE_APPROACH:
      return "approach";
    case ifar::exec_status_t::MODE_PUSH:
      return "push";
    case ifar::exec_status_t::MODE_REPLAN_WAIT:
      return "replan-wait";
    case ifar::exec_status_t::MODE_STOP:
      return "stop";
    case ifar::exec_status_t::MODE_E_STOP:
      return "e-stop";
    case ifar::exec_status_t::MODE_ARRIVED:
      return "arrived";
    default:
      return "unknown";
  }
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Sends a navigation goal (GOAL, goal_t) to the planner"};
  std::vector<double> position;  // X,Y
  std::int64_t goal_id = 0;
  bool cancel = false;
  int repeats = 3;
  double wait_s = 0.0;
  double delay_s = 0.0;
  std::string url;
  ifar::common::addCoordinatesOption(app, "goal", position, "X,Y", 2, 2,
                                     "goal position in metres, world frame (not needed with --cancel)");
  app.add_option("--id", goal_id, "goal id (default: the current time in seconds)");
  app.add_flag("--cancel", cancel, "cancel the goal with this id instead");
  app.add_option("--repeats", repeats, "how many times to send it, 0.2 s apart")
      ->check(ifar::common::atLeast(1))
      ->capture_default_str();
  app.add_option("--wait", wait_s,
                 "then wait up to this many seconds for EXEC_STATUS to report the goal reached, resending "
                 "the goal every second; exit 1 if it is not reached");
  app.add_option(
      "--delay", delay_s,
      "seconds to wait before sending (a launch file starts it beside the daemons, without a shell)");
  app.add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  if (position.empty() && !cancel) {
    std::cerr << "ifar-goal: error: give the goal as X,Y in metres, e.g. ifar goal 8,26\n";
    return 2;
  }
  if (!std::isfinite(wait_s) || wait_s < 0.0 ||
      !(std::isfinite(delay_s) && delay_s >= 0.0 && delay_s <= 3600.0)) {
    std::cerr << "ifar-goal: error: --wait and --delay must be finite numbers, --wait not negative, --delay "
                 "between 0 and 3600 s\n";
    return 2;
  }
  const double x = position.empty() ? 0.0 : position[0];
  const double y = position.empty() ? 0.0 : position[1];
  // Before the bus is opened: until then SIGTERM ends the process as usual.
  std::this_thread::sleep_for(std::chrono::duration<double>(delay_s));

  auto logger = std::make_shared<spdlog::logger>("goal", std::make_shared<spdlog::sinks::null_sink_mt>());
  std::unique_ptr<ifar::bus::RunLoop> loop;
  try {
    loop = std::make_unique<ifar::bus::RunLoop>(ifar::bus::resolveLcmUrl(url), logger);
  } catch (const std::exception& error) {
    std::cerr << "ifar-goal: error: " << error.what() << '\n';
    return 1;
  }

  ifar::goal_t goal;
  goal.utime = ifar::common::nowMicroseconds();
  goal.goal_id = goal_id != 0 ? goal_id : goal.utime / ifar::common::kMicrosecondsPerSecond;
  goal.x = x;
  goal.y = y;
  goal.cancel = cancel;
  const auto send = [&] {
    goal.utime = ifar::common::nowMicroseconds();
    loop->publish("GOAL", goal);
  };

  int sent = 1;
  send();
  const int burst = std::max(1, repeats);
  loop->every(0.2, [&] {
    if (sent < burst) {
      send();
      ++sent;
    }
  });
  std::cout << (cancel ? "cancelled goal " : "sent goal ") << goal.goal_id << " (" << x << ", " << y << ")\n"
            << std::flush;

  const bool waiting = wait_s > 0.0 && !cancel;
  bool arrived = false;
  ifar::exec_status_t last_status;
  bool have_status = false;
  if (waiting) {
    loop->every(1.0, send);
    loop->subscribe<ifar::exec_status_t>("EXEC_STATUS", [&](const ifar::exec_status_t& status, std::int64_t) {
      if (status.goal_id != goal.goal_id) {
        return;
      }
      last_status = status;
      have_status = true;
      if (status.mode == ifar::exec_status_t::MODE_ARRIVED) {
        arrived = true;
        loop->stop();
      }
    });
  }
  const double run_s = waiting ? wait_s : 0.2 * burst;
  const std::int64_t deadline = ifar::common::monotonicMicroseconds() +
                                static_cast<std::int64_t>(run_s * ifar::common::kMicrosecondsPerSecond);
  while (!loop->stopping() && ifar::common::monotonicMicroseconds() < deadline) {
    loop->spinOnce(50);
  }
  if (!waiting) {
    return 0;
  }
  if (arrived) {
    std::cout << "goal " << goal.goal_id << " reached (" << last_status.pushes << " pushes, "
              << last_status.replans << " replans)\n";
    return 0;
  }
  std::cout << "goal " << goal.goal_id << " not reached within " << wait_s << " s";
  if (have_status) {
    std::cout << "; executive: " << modeName(last_status.mode) << ", " << last_status.reason;
  } else {
    std::cout << "; no EXEC_STATUS for this goal";
  }
  std::cout << '\n';
  return 1;
}
