// ifar-import: converts a namosim SVG, a MovingAI .map or a map_server PGM+YAML into an ifar world file.

#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/vehicle.hpp"
#include "sim/importers/grid_importer.hpp"
#include "sim/importers/namosim_svg_importer.hpp"
#include "sim/world/world_file.hpp"

namespace {

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app("Import a namosim SVG, MovingAI .map or map_server .yaml (PGM) as an ifar world file",
               "ifar-import");
  std::string input;
  std::string out;
  std::optional<double> scale;
  double cell_size = 1.0;
  std::string vehicle_path;
  std::vector<double> start;
  std::vector<double> goal;
  app.add_option("INPUT", input, "file.svg, file.map or file.yaml (map_server)")->required();
  app.add_option("--out", out, "world file to write (default: standard output)");
  app.add_option(
      "--scale", scale,
      "SVG only: metres per SVG unit (default: the namosim robot's diameter becomes the vehicle width)");
  app.add_option("--cell-size", cell_size, ".map only: metres per cell")->capture_default_str();
  app.add_option("--vehicle", vehicle_path, "vehicle.yaml whose width_m sets the SVG scale (default 0.7 m)");
  app.add_option("--start", start,
                 "grid maps: start x y [heading_rad] in metres (default: free cell nearest the centre)")
      ->expected(2, 3);
  app.add_option("--goal", goal, "grid maps: goal x y in metres")->expected(2);
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
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

  std::optional<ifar::sim::WorldResult> result;
  if (endsWith(input, ".svg")) {
    ifar::sim::NamosimImportSettings settings;
    settings.vehicle_width_m = vehicle.width_m;
    settings.metres_per_unit = scale;
    const auto import = ifar::sim::importNamosimSvg(input, settings);
    if (import.world.ok()) {
      std::cerr << "scale " << import.metres_per_unit << " m per SVG unit (robot diameter "
                << import.robot_diameter_units << " units)\n";
    }
    result = import.world;
  } else {
    ifar::sim::GridImportSettings settings;
    settings.movingai_cell_size_m = cell_size;
    if (!start.empty()) {
      settings.start = ifar::geometry::Pose2{start[0], start[1], start.size() > 2 ? start[2] : 0.0};
    }
    if (!goal.empty()) {
      settings.goals.push_back(ifar::geometry::Point(goal[0], goal[1]));
    }
    result = ifar::sim::importGridMapFile(input, settings);
  }
  if (!result->ok()) {
    std::cerr << "error: " << result->error() << "\n";
    return ifar::common::kBadInputExitCode;
  }
  if (out.empty()) {
    std::cout << ifar::sim::formatWorld(result->world());
    return 0;
  }
  const auto error = ifar::sim::saveWorldFile(result->world(), out);
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  std::cerr << "wrote " << out << ": " << result->world().obstacles.size() << " obstacles, "
            << result->world().objects.size() << " movable objects, " << result->world().goals.size()
            << " goals\n";
  return 0;
}
