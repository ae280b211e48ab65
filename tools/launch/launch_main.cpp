// ifar launch CONFIG: starts the processes a launch file lists (simulator or not, drivers, planner,
// executive, logger), prefixes their output with their names, restarts those marked respawn, and stops
// them all cleanly on Ctrl-C.

#include <unistd.h>

#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config_search.hpp"
#include "tools/launch/launch_config.hpp"
#include "tools/launch/supervisor.hpp"

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
    std::cout << "ifar launch: " << found->path << " (" << found->origin << ")" << std::endl;
    spec = ifar::launch::loadLaunchSpec(ifar::common::ConfigNode::loadFile(found->path));
  } catch (const ifar::common::ConfigError& error) {
    std::cerr << "ifar-launch: error: " << error.what() << std::endl;
    return 2;
  }
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::string program_directory = error ? std::string(".") : self.parent_path().string();
  ifar::launch::Supervisor supervisor(std::move(spec), program_directory, std::cout,
                                      !no_colour && isatty(STDOUT_FILENO) != 0);
  const auto result = supervisor.run(duration_s);
  return result.exit_code;
}
