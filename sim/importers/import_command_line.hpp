#pragma once
// The importer options `ifar import`, `ifar run` and `ifar render` share, so that a namosim SVG, a MovingAI
// .map or a map_server .yaml is read the same way by each: --scale, --robot, --curve-tolerance (SVG),
// --cell-size (.map) and --start (grid maps, and SVGs that draw no robot).

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "sim/importers/world_loader.hpp"

namespace ifar::sim {

struct ImportCommandLine {
  std::optional<double> scale;
  std::string robot;
  std::optional<double> curve_tolerance_m;
  double cell_size_m = 1.0;
  std::vector<double> start;  // X,Y[,HEADING_RAD]; empty when not given
};

/// Adds the options to `app` in the group "Map import".
void addImportOptions(CLI::App& app, ImportCommandLine& options);

/// The settings the options make, the SVG scale following `vehicle_width_m` unless --scale; nullopt with
/// `error` ("--cell-size: must be a positive number of metres, got -1") when a value is out of range.
std::optional<WorldImportSettings> importSettings(const ImportCommandLine& options, double vehicle_width_m,
                                                  std::string& error);

/// Writes the load's note and each warning ("warning: ...") to `out`, one a line.
void printImportReport(const WorldLoad& load, std::ostream& out);

}  // namespace ifar::sim
