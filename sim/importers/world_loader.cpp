#include "sim/importers/world_loader.hpp"

#include <sstream>

#include "common/config.hpp"
#include "sim/world/world_file.hpp"

namespace ifar::sim {
namespace {

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

const char* worldFormatName(WorldFormat format)
{
  switch (format) {
    case WorldFormat::NamosimSvg:
      return "namosim SVG";
    case WorldFormat::MovingAiMap:
      return "MovingAI map";
    case WorldFormat::MapServerYaml:
      return "map_server map";
    case WorldFormat::WorldYaml:
      break;
  }
  return "world file";
}

WorldFormat detectWorldFormat(const std::string& path, WorldFormat other_names)
{
  if (endsWith(path, ".svg")) {
    return WorldFormat::NamosimSvg;
  }
  if (endsWith(path, ".map")) {
    return WorldFormat::MovingAiMap;
  }
  if (endsWith(path, ".yaml") || endsWith(path, ".yml")) {
    try {
      const common::ConfigNode root = common::ConfigNode::loadFile(path);
      if (root.has("image") && root.has("resolution")) {
        return WorldFormat::MapServerYaml;
      }
    } catch (const common::ConfigError&) {
      // The world file loader reads it again and names the problem.
      return WorldFormat::WorldYaml;
    }
    return WorldFormat::WorldYaml;
  }
  return other_names;
}

WorldLoad loadAnyWorld(const std::string& path, const WorldImportSettings& settings)
{
  WorldLoad load;
  load.format = detectWorldFormat(path, settings.other_names);
  switch (load.format) {
    case WorldFormat::WorldYaml:
      load.world = loadWorldFile(path);
      break;
    case WorldFormat::NamosimSvg: {
      NamosimImport import = importNamosimSvg(path, settings.namosim);
      load.world = std::move(import.world);
      load.warnings = std::move(import.warnings);
      load.incomplete = import.incomplete;
      if (load.world.ok()) {
        std::ostringstream note;
        note << "scale " << import.metres_per_unit << " m per SVG unit";
        if (import.robot_diameter_units > 0.0) {
          note << " (robot '" << import.vehicle_robot << "', " << import.robot_diameter_units
               << " units across)";
        }
        load.note = note.str();
      }
      break;
    }
    case WorldFormat::MovingAiMap:
    case WorldFormat::MapServerYaml:
      load.world = importGridMapFile(path, settings.grid);
      break;
  }
  return load;
}

}  // namespace ifar::sim
