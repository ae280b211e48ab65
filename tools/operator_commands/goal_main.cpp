// ifar goal X Y: sends a navigation goal on GOAL (a few times, so a lossy link or a late subscriber still
// gets it; the planner treats repeats of one goal_id as one goal).

#include <chrono>
#include <cmath>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "common/bus/run_loop.hpp"
#include "common/time.hpp"
#include "ifar/goal_t.hpp"

int main(int argc, char** argv)
{
  CLI::App app{"Sends a navigation goal (GOAL, goal_t) to the planner"};
  double x = 0.0;
  double y = 0.0;
  std::int64_t goal_id = 0;
  bool cancel = false;
  int repeats = 3;
  std::string url;
  app.add_option("x", x, "goal x in metres, world frame")->required();
  app.add_option("y", y, "goal y in metres, world frame")->required();
  app.add_option("--id", goal_id, "goal id (default: the current time in seconds)");
  app.add_flag("--cancel", cancel, "cancel the goal with this id instead");
  app.add_option("--repeats", repeats, "how many times to send it, 0.2 s apart")->capture_default_str();
  app.add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  CLI11_PARSE(app, argc, argv);
  if (!std::isfinite(x) || !std::isfinite(y)) {
    std::cerr << "ifar-goal: error: the goal must be finite numbers" << std::endl;
    return 2;
  }
  lcm::LCM bus(ifar::bus::resolveLcmUrl(url));
  if (!bus.good()) {
    std::cerr << "ifar-goal: error: cannot start LCM" << std::endl;
    return 1;
  }
  ifar::goal_t goal;
  goal.utime = ifar::common::nowMicroseconds();
  goal.goal_id = goal_id != 0 ? goal_id : goal.utime / ifar::common::kMicrosecondsPerSecond;
  goal.x = x;
  goal.y = y;
  goal.cancel = cancel;
  for (int index = 0; index < std::max(1, repeats); ++index) {
    bus.publish("GOAL", &goal);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  std::cout << (cancel ? "cancelled goal " : "sent goal ") << goal.goal_id << " (" << x << ", " << y << ")"
            << std::endl;
  return 0;
}
