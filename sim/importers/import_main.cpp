// ifar-import: converts a namosim SVG, a MovingAI .map or a map_server PGM+YAML into an ifar world file.
// Exit code 0 when the world is complete, 1 when it was written but lacks walls, a robot or goals (each
// named in a warning), 2 on bad input or a file that cannot be written.

#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/config_search.hpp"
#include "common/vehicle.hpp"
#include "sim/importers/import_command_line.hpp"
#include "sim/importers/world_loader.hpp"
#include "sim/world/world_file.hpp"

namespace {

constexpr int kExitIncomplete = 1;

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app(
      "Import a namosim SVG, MovingAI .map or map_server .yaml (PGM) as an ifar world file.\nExit code 0 "
      "when "
      "the world is complete, 1 when it was written but has no walls, no robot or no goals (warnings name "
      "them), 2 on bad input.",
      "ifar-import");
  std::string input;
  std::string out;
  std::string vehicle_path;
  std::vector<double> goal;
  ifar::sim::ImportCommandLine import_options;
  app.add_option("INPUT", input, "file.svg, file.map or file.yaml (map_server)")->required();
  app.add_option("--out", out, "world file to write (default: standard output)");
  app.add_option("--vehicle", vehicle_path, "vehicle.yaml whose width_m sets the SVG scale (default 0.7 m)");
  ifar::sim::addImportOptions(app, import_options);
  ifar::common::addCoordinatesOption(app, "--goal", goal, "X,Y", 2, 2, "grid maps: a goal in metres");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  ifar::common::VehicleSettings vehicle;
  std::string vehicle_used = "built-in vehicle";  // said with the result
  if (!vehicle_path.empty()) {
    try {
      const ifar::common::FoundConfig found = ifar::common::resolveConfigFile(vehicle_path, "vehicle.yaml");
      vehicle = ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(found.path));
      vehicle_used = "vehicle " + found.path;
    } catch (const ifar::common::ConfigError& error) {
      std::cerr << "error: " << error.what() << "\n";
      return ifar::common::kBadInputExitCode;
    }
  }
  std::string problem;
  auto settings = ifar::sim::importSettings(import_options, vehicle.width_m, problem);
  if (!settings) {
    std::cerr << "error: " << problem << "\n";
    return ifar::common::kBadInputExitCode;
  }
  settings->other_names = ifar::sim::WorldFormat::MovingAiMap;
  if (!goal.empty()) {
    settings->grid.goals.push_back(ifar::geometry::Point(goal[0], goal[1]));
  }

  const ifar::sim::WorldLoad load = ifar::sim::loadAnyWorld(input, *settings);
  if (!load.world.ok()) {
    std::cerr << "error: " << load.world.error() << "\n";
    return ifar::common::kBadInputExitCode;
  }
  ifar::sim::printImportReport(load, std::cerr);
  const auto& world = load.world.world();
  if (out.empty()) {
    std::cout << ifar::sim::formatWorld(world);
  } else {
    const auto error = ifar::sim::saveWorldFile(world, out);
    if (!error.empty()) {
      std::cerr << "error: " << error << "\n";
      return ifar::common::kOutputFailedExitCode;
    }
    std::cerr << "wrote " << out << ": " << world.obstacles.size() << " obstacles, " << world.objects.size()
              << " movable objects, " << world.goals.size() << " goals (" << vehicle_used << ")\n";
  }
  if (load.incomplete) {
    std::cerr << "warning: the world is incomplete (exit code " << kExitIncomplete << ")\n";
    return kExitIncomplete;
  }
  return 0;
}
