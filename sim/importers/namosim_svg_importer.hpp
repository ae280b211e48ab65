#pragma once
// Imports namosim scenario SVGs (the conventions are in namosim_scene.hpp): walls become static obstacles
// (each closed subpath one), movables movable objects, one robot the vehicle (its outline's centre the
// start, its heading mark or `angle` the start heading) and that robot's goals, in its order, the world's
// goals. The other robots are not simulated: each is named in a warning with its goals. SVG user units are
// centimetres with y down in namosim; y is flipped with the viewBox, and by default the whole scene is
// scaled so the vehicle robot's size equals the vehicle's width (the scenarios are drawn for smaller robots).

#include <optional>
#include <string>
#include <vector>

#include "common/geometry/pose2.hpp"
#include "sim/world/world_result.hpp"

namespace ifar::sim {

struct NamosimImportSettings {
  double vehicle_width_m = 0.7;           // the robot's size maps to this by default
  std::optional<double> metres_per_unit;  // overrides the robot-based scale (0.01 = namosim's true size)
  /// The robot that becomes the vehicle: its id ("robot_1") or its position among the file's robots ("1").
  /// Empty: the first.
  std::string robot;
  /// World start (metres, radians) when the vehicle robot is not drawn in the file.
  std::optional<geometry::Pose2> start;
  /// Curves are flattened so that no point of a wall's or object's outline lies farther than this from its
  /// straight pieces in the world; converted to the file's units with the scale.
  double curve_tolerance_m = 0.005;
  /// A subpath whose ends are this close, as a fraction of the viewBox's larger side, is closed (and
  /// consecutive points this close are one): Inkscape's rounding of relative coordinates leaves gaps of
  /// about 1e-6 of the drawing.
  double closing_tolerance = 1e-5;
  double wall_height_m = 2.0;
  double wall_reflectivity = 0.2;
  double object_mass_kg = 30.0;  // namosim has no masses: light enough to push by default
  double object_ground_friction = 0.5;
  double object_height_m = 1.0;
  double object_reflectivity = 0.9;
  /// namosim plans and moves on a grid that ends at the document's extent: a wall this thick just outside
  /// each side of the viewBox keeps the vehicle (and its lidar's world) inside it. 0: no edge walls.
  double edge_wall_thickness_m = 0.2;
};

/// A robot of the file in the world frame, whether or not it became the vehicle.
struct NamosimRobotSummary {
  std::string id;
  std::optional<geometry::Pose2> start;  // empty when the file does not draw the robot
  std::vector<std::string> goal_names;
  std::vector<geometry::Point> goals;
};

struct NamosimImport {
  WorldResult world = WorldResult::failure("not imported");
  double metres_per_unit = 0.0;       // the scale applied
  double robot_diameter_units = 0.0;  // the vehicle robot's size in SVG units (0 when not drawn)
  std::string vehicle_robot;          // id of the robot that became the vehicle (empty: the file has none)
  std::vector<NamosimRobotSummary> robots;  // every robot of the file, in the file's order
  /// Everything the world does not carry that the file has or lacks: robots not simulated, goals and
  /// agents without elements, look-alike elements, the scale's origin when no robot gives it.
  std::vector<std::string> warnings;
  /// No walls, no drawn robot (and no start given) or no goals: the world is written, but a command should
  /// not treat it as a complete scenario (ifar import exits 1).
  bool incomplete = false;
};

/// Reads and converts an SVG file; errors name the file and the element (id and line).
NamosimImport importNamosimSvg(const std::string& path, const NamosimImportSettings& settings);

/// Same for SVG text; `source_name` stands in for the file name in messages.
NamosimImport parseNamosimSvg(const std::string& text, const std::string& source_name,
                              const NamosimImportSettings& settings);

}  // namespace ifar::sim
