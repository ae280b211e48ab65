#pragma once
// Any world or map file the project reads, through the importers `ifar import` uses: a world YAML
// (docs/worlds.md), a namosim scenario SVG, a MovingAI .map, or a map_server .yaml (its PGM beside it).
// A .yaml is a map_server description when its top level has the keys `image` and `resolution` (a world
// file has neither), else a world file; a name ending in neither .svg, .map, .yaml nor .yml is read as a
// world file.

#include <string>
#include <vector>

#include "sim/importers/grid_importer.hpp"
#include "sim/importers/namosim_svg_importer.hpp"
#include "sim/world/world_result.hpp"

namespace ifar::sim {

enum class WorldFormat { WorldYaml, NamosimSvg, MovingAiMap, MapServerYaml };

/// "world file", "namosim SVG", "MovingAI map", "map_server map".
const char* worldFormatName(WorldFormat format);

/// The format of `path`, by its extension and, for .yaml/.yml, by its keys (an unreadable YAML counts as a
/// world file, whose loader then names the problem); `other_names` for any other extension.
WorldFormat detectWorldFormat(const std::string& path, WorldFormat other_names = WorldFormat::WorldYaml);

struct WorldImportSettings {
  NamosimImportSettings namosim;
  GridImportSettings grid;
  WorldFormat other_names = WorldFormat::WorldYaml;
};

struct WorldLoad {
  WorldFormat format = WorldFormat::WorldYaml;
  WorldResult world = WorldResult::failure("not loaded");
  /// What the file has that the world does not carry, or lacks (namosim SVGs; see NamosimImport).
  std::vector<std::string> warnings;
  /// No walls, no robot or no goals (namosim SVGs): usable, but not a complete scenario.
  bool incomplete = false;
  /// One line on how the file was read, e.g. "scale 0.0477 m per SVG unit (robot 'robot_0', 14.67 units)".
  std::string note;
};

WorldLoad loadAnyWorld(const std::string& path, const WorldImportSettings& settings);

}  // namespace ifar::sim
