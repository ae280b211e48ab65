#pragma once
// Readers for grid map files. Failures are values: `error` names the file, the line (or YAML key) and
// the problem, e.g. "maps/a.map:7: row has 511 cells, expected 512". Only regular files are read, and no
// reader allocates for a size its header claims before checking the file can hold it.

#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/grid_map/grid_map.hpp"

namespace ifar::grid_map {

/// How large a map a reader accepts: the header's width x height is checked against this and against
/// the bytes the file still holds before anything is allocated.
struct MapReadLimits {
  std::int64_t max_cells = 400'000'000;  // 400 MB of cells; the largest real maps are below 10^8
};

struct MapReadResult {
  GridMap map;
  std::string error;  // empty on success
  bool ok() const { return error.empty(); }
};

/// MovingAI / GPPC .map ("type octile", "height H", "width W", "map", H rows of W characters).
/// '.', 'G', 'S' are free; '@', 'O', 'T', 'W' blocked; anything else is an error. Row r becomes y = r,
/// resolution 1, origin (0, 0): grid corners are the GPPC lattice points.
MapReadResult readMovingAiMap(const std::string& path, const MapReadLimits& limits = {});

/// One query of a MovingAI .scen file. Coordinates are lattice points (GPPC any-angle: corners).
struct Scenario {
  int bucket = 0;
  std::string map_name;
  int map_width = 0;
  int map_height = 0;
  geometry::Point start = geometry::Point::Zero();
  geometry::Point goal = geometry::Point::Zero();
  double optimal_length = 0.0;
};

struct ScenarioReadResult {
  std::vector<Scenario> scenarios;
  std::string error;
  bool ok() const { return error.empty(); }
};

/// A .scen file ("version 1" then one tab-separated query a line; "version 1.0" accepted).
ScenarioReadResult readMovingAiScenarios(const std::string& path);

/// A map_server description (YAML: image, resolution, origin [x, y, yaw], negate, occupied_thresh,
/// free_thresh, optional mode "trinary"/"scale") and its PGM (P5 8/16 bit or P2), relative to the YAML.
/// Occupancy p = (max - value) / max (value / max when negate); p > occupied_thresh is Blocked,
/// p < free_thresh Free, the rest Unknown. Image row 0 is the top: it becomes y = height - 1 so that
/// y points up. A non-zero yaw is rejected (not supported).
MapReadResult readMapServer(const std::string& yaml_path, const MapReadLimits& limits = {});

/// Picks the reader by extension: ".yaml"/".yml" map_server, anything else MovingAI.
MapReadResult readGridMapFile(const std::string& path, const MapReadLimits& limits = {});

}  // namespace ifar::grid_map
