#include "sim/importers/import_command_line.hpp"

#include <cmath>

#include "common/command_line.hpp"

namespace ifar::sim {
namespace {

bool positiveFinite(double value)
{
  return std::isfinite(value) && value > 0.0;
}

}  // namespace

void addImportOptions(CLI::App& app, ImportCommandLine& options)
{
  const std::string group = "Map import";
  app.add_option("--scale", options.scale,
                 "SVG: metres per SVG unit (default: the vehicle robot's size becomes the vehicle's width)")
      ->group(group);
  app.add_option("--robot", options.robot,
                 "SVG: the robot that becomes the vehicle, by id (robot_1) or index (1); default the first. "
                 "Its goals, in its order, are the world's goals; the other robots are not simulated")
      ->group(group);
  app.add_option("--curve-tolerance", options.curve_tolerance_m,
                 "SVG: metres by which flattened curves may deviate from the drawing (default 0.005)")
      ->group(group);
  app.add_option("--cell-size", options.cell_size_m, ".map: metres per cell")
      ->capture_default_str()
      ->group(group);
  common::addCoordinatesOption(
      app, "--start", options.start, "X,Y[,HEADING_RAD]", 2, 3,
      "Grid maps, and SVGs that draw no robot: start in metres (default: the free spot "
      "nearest the centre of the grid or the SVG's viewBox)")
      ->group(group);
}

std::optional<WorldImportSettings> importSettings(const ImportCommandLine& options, double vehicle_width_m,
                                                  std::string& error)
{
  WorldImportSettings settings;
  if (options.scale && !positiveFinite(*options.scale)) {
    error =
        "--scale: must be a positive number of metres per SVG unit, got " + std::to_string(*options.scale);
    return std::nullopt;
  }
  if (options.curve_tolerance_m && !positiveFinite(*options.curve_tolerance_m)) {
    error = "--curve-tolerance: must be a positive number of metres, got " +
            std::to_string(*options.curve_tolerance_m);
    return std::nullopt;
  }
  if (!positiveFinite(options.cell_size_m)) {
    error = "--cell-size: must be a positive number of metres, got " + std::to_string(options.cell_size_m);
    return std::nullopt;
  }
  settings.namosim.vehicle_width_m = vehicle_width_m;
  settings.namosim.metres_per_unit = options.scale;
  settings.namosim.robot = options.robot;
  if (options.curve_tolerance_m) {
    settings.namosim.curve_tolerance_m = *options.curve_tolerance_m;
  }
  settings.grid.movingai_cell_size_m = options.cell_size_m;
  if (!options.start.empty()) {
    const geometry::Pose2 start{options.start[0], options.start[1],
                                options.start.size() > 2 ? options.start[2] : 0.0};
    settings.grid.start = start;
    settings.namosim.start = start;
  }
  return settings;
}

void printImportReport(const WorldLoad& load, std::ostream& out)
{
  if (!load.note.empty()) {
    out << load.note << "\n";
  }
  for (const auto& warning : load.warnings) {
    out << "warning: " << warning << "\n";
  }
}

}  // namespace ifar::sim
