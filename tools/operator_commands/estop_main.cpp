// ifar estop [--release]: engages (or releases) the emergency stop on E_STOP. While engaged the message is
// resent at 5 Hz until Ctrl-C, so a restarted executive learns it at once; --once sends it a single time.

#include <chrono>
#include <csignal>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/time.hpp"
#include "ifar/e_stop_t.hpp"

int main(int argc, char** argv)
{
  CLI::App app{"Engages or releases the emergency stop (E_STOP, e_stop_t)"};
  bool release = false;
  bool once = false;
  std::string reason = "operator";
  std::string url;
  app.add_flag("--release", release, "release the stop instead of engaging it");
  app.add_flag("--once", once, "send one message and exit instead of resending until Ctrl-C");
  app.add_option("--reason", reason, "why, for the logs")->capture_default_str();
  app.add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  lcm::LCM bus(ifar::bus::resolveLcmUrl(url));
  if (!bus.good()) {
    std::cerr << "ifar-estop: error: cannot start LCM\n";
    return 1;
  }
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  ifar::e_stop_t stop;
  stop.engaged = !release;
  stop.source = "ifar estop";
  stop.reason = reason;
  std::cout << (release ? "releasing" : "engaging") << " the emergency stop"
            << (once || release ? "" : " (resending until Ctrl-C)") << '\n'
            << std::flush;
  while (true) {
    stop.utime = ifar::common::nowMicroseconds();
    bus.publish("E_STOP", &stop);
    if (once || release) {
      return 0;
    }
    const timespec wait{0, 200'000'000};
    if (sigtimedwait(&signals, nullptr, &wait) > 0) {
      return 0;
    }
  }
}
