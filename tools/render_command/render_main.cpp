// ifar-render: a PNG picture of a world file.

#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/vehicle.hpp"
#include "sim/world/world_file.hpp"
#include "viz/world_picture.hpp"

int main(int argc, char** argv)
{
  CLI::App app("Draw a simulator world file (walls, movable objects, start, goals) as a PNG", "ifar-render");
  std::string world_path;
  std::string out;
  double resolution = 0.0;
  std::string vehicle_path;
  app.add_option("WORLD", world_path, "world file (YAML, docs/worlds.md)")->required();
  app.add_option("--out", out, "PNG to write (default: the world file's name with .png)");
  app.add_option("--resolution", resolution, "metres per pixel (default 0.05, coarser for large worlds)");
  app.add_option(
      "--vehicle", vehicle_path,
      "vehicle.yaml for the push limit and footprint (default: built-in values of config/vehicle.yaml)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  const auto loaded = ifar::sim::loadWorldFile(world_path);
  if (!loaded.ok()) {
    std::cerr << "error: " << loaded.error() << "\n";
    return ifar::common::kBadInputExitCode;
  }
  ifar::common::VehicleSettings vehicle;
  if (!vehicle_path.empty()) {
    try {
      vehicle = ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(vehicle_path));
    } catch (const ifar::common::ConfigError& error) {
      std::cerr << "error: " << error.what() << "\n";
      return ifar::common::kBadInputExitCode;
    }
  }
  if (resolution < 0.0 || (app.count("--resolution") > 0 && !(resolution > 0.0))) {
    std::cerr << "error: --resolution must be positive metres per pixel\n";
    return ifar::common::kBadInputExitCode;
  }
  const auto& world = loaded.world();
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
    return 1;
  }
  std::cerr << "wrote " << out << " (" << canvas.widthPixels() << " x " << canvas.heightPixels()
            << " pixels, " << resolution << " m per pixel)\n";
  return 0;
}
