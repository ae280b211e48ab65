#pragma once
// Imports namosim scenario SVGs: paths with type="wall" become static obstacles, type="movable" movable
// objects, the path with id "robot_0" the start, paths with ids "goal_N" the goals. SVG user units are
// centimetres with y down; y is flipped with the viewBox, and by default the whole scene is scaled so
// the namosim robot's diameter equals the vehicle's width (the scenarios are drawn for a smaller robot).

#include <optional>
#include <string>

#include "sim/world/world_result.hpp"

namespace ifar::sim {

struct NamosimImportSettings {
  double vehicle_width_m = 0.7;           // the robot's diameter maps to this by default
  std::optional<double> metres_per_unit;  // overrides the robot-based scale (0.01 = true size)
  double wall_height_m = 2.0;
  double wall_reflectivity = 0.2;
  double object_mass_kg = 30.0;  // namosim has no masses: light enough to push by default
  double object_ground_friction = 0.5;
  double object_height_m = 1.0;
  double object_reflectivity = 0.9;
  int curve_segments = 8;  // straight pieces per Bezier curve
};

struct NamosimImport {
  WorldResult world;
  double metres_per_unit = 0.0;       // the scale applied
  double robot_diameter_units = 0.0;  // the namosim robot's diameter in SVG units (0 when not found)
};

/// Reads and converts an SVG file; errors name the file and the element (id and line).
NamosimImport importNamosimSvg(const std::string& path, const NamosimImportSettings& settings);

/// Same for SVG text; `source_name` stands in for the file name in messages.
NamosimImport parseNamosimSvg(const std::string& text, const std::string& source_name,
                              const NamosimImportSettings& settings);

}  // namespace ifar::sim
