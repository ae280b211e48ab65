// ifar-can (run as `ifar can ...`): the CAN bus from the command line, on whichever bus can.yaml
// (or --bus) names, so the LCM bridge and SocketCAN look the same to a person debugging.
//   ifar can dump [-l FILE] [--count N]     print frames in candump -l format (or append them to FILE)
//   ifar can play FILE [--speed S]          send a candump log's frames with their recorded timing
//   ifar can up [--wait S] [--dry-run]      bring the SocketCAN interface up at the configured bit rate
//   ifar can down [--dry-run]               take it down (both run ip link; the ifar-can unit uses them)
// Both take --config FILE (default can.yaml on the configuration search path), --bus socketcan|lcm,
// --interface, --channel,
// --lcm-url.

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/config_search.hpp"
#include "drivers/can/candump_log.hpp"
#include "drivers/can/interface_setup.hpp"
#include "drivers/can/open_bus.hpp"

namespace {

constexpr const char* kDefaultConfig = "can.yaml";

struct Options {
  std::string config;  // "" = kDefaultConfig on the configuration search path, when there is one
  std::string bus_kind;
  std::string interface;
  std::string channel;
  std::string lcm_url;
  std::string output;
  std::string input;
  std::int64_t count = 0;
  double speed = 1.0;
  double wait_s = 0.0;
  bool dry_run = false;
};

std::int64_t steadyMicroseconds()
{
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

ifar::can::BusSettings resolveBus(const Options& options)
{
  ifar::can::BusSettings settings;
  // The default is optional (the tool runs anywhere); a file asked for by name is not.
  std::optional<ifar::common::FoundConfig> found =
      options.config.empty() ? ifar::common::ConfigSearchPath::standard().find(kDefaultConfig)
                             : ifar::common::resolveConfigFile(options.config, kDefaultConfig);
  if (found) {
    std::cerr << "ifar can: configuration " << found->path << " (" << found->origin << ")\n";
    settings = ifar::can::loadBusSettings(ifar::common::ConfigNode::loadFile(found->path));
  }
  if (!options.bus_kind.empty()) {
    if (options.bus_kind == "socketcan") {
      settings.kind = ifar::can::BusKind::kSocketCan;
    } else if (options.bus_kind == "lcm") {
      settings.kind = ifar::can::BusKind::kLcm;
    } else {
      throw std::invalid_argument("--bus '" + options.bus_kind + "' is not socketcan or lcm");
    }
  }
  if (settings.kind == ifar::can::BusKind::kCandump) {
    settings.kind = ifar::can::BusKind::kLcm;  // a log is what we read or write here, not the bus
  }
  if (!options.interface.empty())
    settings.interface = options.interface;
  if (!options.channel.empty())
    settings.lcm_channel = options.channel;
  return settings;
}

int dump(ifar::can::CanBus& bus, const Options& options, const std::string& interface_name)
{
  std::ofstream file;
  if (!options.output.empty()) {
    file.open(options.output, std::ios::app);
    if (!file) {
      std::cerr << "ifar can dump: cannot open '" << options.output << "' for writing\n";
      return ifar::common::kOutputFailedExitCode;
    }
  }
  std::ostream& out = options.output.empty() ? std::cout : file;
  std::int64_t written = 0;
  while (options.count <= 0 || written < options.count) {
    const auto received = bus.receive(std::chrono::milliseconds(200));
    if (received.status == ifar::can::IoStatus::kError) {
      std::cerr << "ifar can dump: " << received.error << "\n";
      return 1;
    }
    if (received.status != ifar::can::IoStatus::kOk) {
      continue;
    }
    out << ifar::can::formatCandumpLine(received.frame, interface_name) << "\n" << std::flush;
    ++written;
  }
  return 0;
}

int play(ifar::can::CanBus& bus, const Options& options)
{
  auto opened = ifar::can::CandumpLogBus::open(options.input, "");
  if (!opened.bus) {
    std::cerr << "ifar can play: " << opened.error << "\n";
    return ifar::common::kBadInputExitCode;
  }
  std::int64_t first_log_us = -1;
  const std::int64_t start_us = steadyMicroseconds();
  std::int64_t sent = 0;
  while (true) {
    const auto next = opened.bus->receive(std::chrono::microseconds(0));
    if (next.status != ifar::can::IoStatus::kOk)
      break;
    if (first_log_us < 0)
      first_log_us = next.frame.timestamp_us;
    if (options.speed > 0.0) {
      const auto due_us =
          start_us + static_cast<std::int64_t>(static_cast<double>(next.frame.timestamp_us - first_log_us) /
                                               options.speed);
      const std::int64_t wait_us = due_us - steadyMicroseconds();
      if (wait_us > 0)
        std::this_thread::sleep_for(std::chrono::microseconds(wait_us));
    }
    const auto result = bus.send(next.frame);
    if (result.status != ifar::can::IoStatus::kOk) {
      std::cerr << "ifar can play: " << result.error << "\n";
      return 1;
    }
    ++sent;
  }
  const auto skipped = opened.bus->counters().bad_frames;
  std::cerr << "ifar can play: sent " << sent << " frames, skipped " << skipped << " bad lines\n";
  if (sent == 0 && skipped > 0) {
    // Every line was bad: the file is not a candump log, and playing nothing is not a success.
    std::cerr << "ifar can play: error: no line of " << options.input << " is a candump -l frame\n";
    return ifar::common::kBadInputExitCode;
  }
  return 0;
}

/// Runs `command` (found on PATH) and waits for it; its exit code, 127 when it could not start.
int runCommand(const ifar::can::CommandLine& command)
{
  std::vector<char*> argv;
  for (const std::string& word : command) {
    argv.push_back(const_cast<char*>(word.c_str()));  // posix_spawnp's signature predates const
  }
  argv.push_back(nullptr);
  pid_t child = 0;
  if (posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
    return 127;
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// ifar can up / down: the ip link commands for the configured interface, run (or with --dry-run printed).
int setUpInterface(const ifar::can::BusSettings& settings, const Options& options, bool up)
{
  const char* action = up ? "up" : "down";
  if (settings.kind != ifar::can::BusKind::kSocketCan) {
    std::cerr << "ifar can " << action << ": bus.kind is " << ifar::can::toString(settings.kind)
              << ", not socketcan: no interface to bring " << action << "\n";
    return 0;
  }
  if (up && !options.dry_run) {
    // At boot the interface may appear after this starts (a USB adapter, a slow driver).
    const std::string device = "/sys/class/net/" + settings.interface;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.wait_s);
    while (access(device.c_str(), F_OK) != 0 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (access(device.c_str(), F_OK) != 0) {
      std::cerr << "ifar can up: no interface '" << settings.interface << "' (" << device << ")"
                << (options.wait_s > 0.0 ? " after waiting " + std::to_string(options.wait_s) + " s" : "")
                << "\n";
      return 1;
    }
  }
  for (const ifar::can::CommandLine& command :
       up ? ifar::can::interfaceUpCommands(settings) : ifar::can::interfaceDownCommands(settings)) {
    // Flushed before the command runs, so its own output follows its line.
    std::cout << ifar::can::commandText(command) << '\n' << std::flush;
    if (options.dry_run) {
      continue;
    }
    const int code = runCommand(command);
    if (code != 0) {
      std::cerr << "ifar can " << action << ": '" << ifar::can::commandText(command) << "' "
                << (code == 127 ? std::string("could not run (is iproute2 installed?)")
                                : "exited with code " + std::to_string(code))
                << "\n";
      return 1;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app("CAN bus tool: dump frames in candump format, or play a candump log onto the bus", "ifar can");
  Options options;
  app.add_option("--config", options.config,
                 "can.yaml whose `bus` section is used (default: can.yaml on the configuration search path "
                 "when there is one)");
  app.add_option("--bus", options.bus_kind, "socketcan or lcm (overrides the config)");
  app.add_option("--interface", options.interface, "SocketCAN interface (e.g. can0, vcan0)");
  app.add_option("--channel", options.channel, "LCM channel carrying can_frame_t (e.g. CAN_VEHICLE)");
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  app.fallthrough();  // set before the subcommands, which inherit it: `ifar can dump --bus lcm` works
  auto* dump_command = app.add_subcommand("dump", "print received frames in candump -l format");
  dump_command->add_option("-l,--log", options.output, "append to this file instead of printing");
  dump_command->add_option("-n,--count", options.count, "stop after this many frames (0 = run until killed)")
      ->check(ifar::common::atLeast(0));
  auto* play_command = app.add_subcommand("play", "send the frames of a candump log with their timing");
  play_command->add_option("file", options.input, "candump -l log")->required();
  play_command->add_option("--speed", options.speed, "time scale; 0 = as fast as possible")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  auto* up_command =
      app.add_subcommand("up", "bring the SocketCAN interface up at the configured bit rate (ip link)");
  up_command->add_option("--wait", options.wait_s, "wait this many seconds for the interface to appear")
      ->check(ifar::common::atLeast(0));
  up_command->add_flag("--dry-run", options.dry_run, "print the ip link commands instead of running them");
  auto* down_command = app.add_subcommand("down", "take the SocketCAN interface down (ip link)");
  down_command->add_flag("--dry-run", options.dry_run, "print the ip link command instead of running it");
  app.require_subcommand(1);
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  try {
    const ifar::can::BusSettings settings = resolveBus(options);
    if (up_command->parsed() || down_command->parsed()) {
      return setUpInterface(settings, options, up_command->parsed());
    }
    lcm::LCM lcm(options.lcm_url);
    if (settings.kind == ifar::can::BusKind::kLcm && !lcm.good()) {
      std::cerr << "ifar can: cannot start LCM (url '" << options.lcm_url << "')\n";
      return 1;
    }
    auto opened = ifar::can::openBus(settings, lcm);
    if (!opened.bus) {
      std::cerr << "ifar can: " << opened.error << "\n";
      return 1;
    }
    const std::string interface_name =
        settings.kind == ifar::can::BusKind::kSocketCan ? settings.interface : settings.lcm_channel;
    return dump_command->parsed() ? dump(*opened.bus, options, interface_name) : play(*opened.bus, options);
  } catch (const ifar::common::ConfigError& error) {
    std::cerr << "ifar can: error: " << error.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& error) {
    std::cerr << "ifar can: error: " << error.what() << "\n";
    return 2;
  }
}
