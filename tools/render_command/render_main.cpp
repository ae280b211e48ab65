// ifar-render: a PNG picture of a world file, or of a namosim SVG, MovingAI .map or map_server .yaml read
// through the importers `ifar import` uses.

#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/config_search.hpp"
#include "common/vehicle.hpp"
#include "sim/importers/import_command_line.hpp"
#include "sim/importers/world_loader.hpp"
#include "viz/world_picture.hpp"

int main(int argc, char** argv)
{
  CLI::App app(
      "Draws a world as a PNG: walls, movable objects, start and goals. From a world file, a namosim SVG, a "
      "MovingAI .map or a map_server .yaml",
      "ifar-render");
  std::string world_path;
  std::string out;
  double resolution = 0.0;
  std::string vehicle_path;
  app.add_option("WORLD", world_path,
                 "world file (YAML, docs/worlds.md), namosim .svg, MovingAI .map or map_server .yaml, or a "
                 "world's name in worlds/ on the configuration search path (demo_room)")
      ->required();
  app.add_option("--out", out, "PNG to write (default: WORLD as given, with .png for its extension)");
  app.add_option("--resolution", resolution, "metres per pixel (default 0.05, coarser for large worlds)");
  app.add_option(
      "--vehicle", vehicle_path,
      "vehicle.yaml for the push limit, the footprint and an SVG's scale (default: built-in values of "
      "config/vehicle.yaml)");
  ifar::sim::ImportCommandLine import_options;
  ifar::sim::addImportOptions(app, import_options);
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
  const auto settings = ifar::sim::importSettings(import_options, vehicle.width_m, problem);
  if (!settings) {
    std::cerr << "error: " << problem << "\n";
    return ifar::common::kBadInputExitCode;
  }
  const auto named = ifar::common::findNamedInput(world_path, "worlds");
  const ifar::sim::WorldLoad load = ifar::sim::loadAnyWorld(named ? named->path : world_path, *settings);
  if (!load.world.ok()) {
    std::cerr << "error: " << load.world.error() << "\n";
    return ifar::common::kBadInputExitCode;
  }
  ifar::sim::printImportReport(load, std::cerr);
  if (resolution < 0.0 || (app.count("--resolution") > 0 && !(resolution > 0.0))) {
    std::cerr << "error: --resolution must be positive metres per pixel\n";
    return ifar::common::kBadInputExitCode;
  }
  const auto& world = load.world.world();
  if (resolution == 0.0) {
    resolution = ifar::viz::defaultResolution(world);
  }
  if (out.empty()) {
    const auto dot = world_path.rfind('.');
    const auto slash = world_path.rfind('/');
    out = (dot != std::string::npos && (slash == std::string::npos || dot > slash) ? world_path.substr(0, dot)
                                                                                   : world_path) +
          ".png";
  }
  const ifar::viz::WorldPictureStyle style;
  auto canvas = ifar::viz::makeWorldCanvas(world, resolution, style);
  ifar::viz::drawWorld(canvas, world, vehicle, style);
  const auto error = canvas.writePng(out);
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return ifar::common::kOutputFailedExitCode;
  }
  std::cerr << "wrote " << out << " (" << canvas.widthPixels() << " x " << canvas.heightPixels()
            << " pixels, " << resolution << " m per pixel; " << vehicle_used << ")\n";
  return 0;
}
