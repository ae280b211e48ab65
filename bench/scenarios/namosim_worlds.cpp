#include "bench/scenarios/namosim_worlds.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

#include "sim/importers/namosim_svg_importer.hpp"

namespace ifar::scenarios {
namespace {

std::vector<std::filesystem::path> svgFiles(const std::string& folder)
{
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
       entry.increment(error)) {
    if (entry->is_regular_file() && entry->path().extension() == ".svg") {
      files.push_back(entry->path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

WorldSetResult namosimWorlds(const std::string& folder, double vehicle_width_m)
{
  WorldSetResult result;
  const std::vector<std::filesystem::path> files =
      folder.empty() ? std::vector<std::filesystem::path>() : svgFiles(folder);
  if (files.empty()) {
    result.notes.push_back("namosim folder '" + folder + "' absent or without .svg files: kind skipped");
    return result;
  }
  for (const std::filesystem::path& file : files) {
    const std::string stem = file.stem().string();
    sim::NamosimImportSettings settings;
    settings.vehicle_width_m = vehicle_width_m;
    const sim::NamosimImport first = sim::importNamosimSvg(file.string(), settings);
    if (!first.world.ok()) {
      result.notes.push_back(stem + ": not imported: " + first.world.error());
      continue;
    }
    if (first.incomplete) {
      // Driven as it stands, such a file measures nothing: with no robot drawn the scale is a guess
      // (1 unit = 1 cm makes a room-sized map a toy one the vehicle cannot stand in) and the start is
      // made up; a file without walls or goals is no scenario either.
      std::string why = stem + ": not driven: not a complete scenario";
      for (const std::string& warning : first.warnings) {
        why.append("; ").append(warning);
      }
      result.notes.push_back(why);
      continue;
    }
    std::vector<std::string> driven_robots;
    for (const sim::NamosimRobotSummary& robot : first.robots) {
      if (!robot.goals.empty()) {
        driven_robots.push_back(robot.id);
      }
    }
    if (driven_robots.empty()) {
      result.notes.push_back(stem + ": no robot has a goal: no task");
      continue;
    }
    for (const std::string& warning : first.warnings) {
      // Every robot with goals gets a world of its own here, so "robot ... not simulated" is not so.
      if (driven_robots.size() < 2 || warning.find("not simulated") == std::string::npos) {
        result.notes.push_back(std::string(stem).append(": ").append(warning));
      }
    }
    for (const std::string& robot : driven_robots) {
      const bool several = driven_robots.size() > 1;
      sim::NamosimImport import = first;
      if (robot != first.vehicle_robot) {
        settings.robot = robot;
        import = sim::importNamosimSvg(file.string(), settings);
      }
      if (!import.world.ok()) {
        result.notes.push_back(std::string(stem)
                                   .append(" robot ")
                                   .append(robot)
                                   .append(": not imported: ")
                                   .append(import.world.error()));
        continue;
      }
      const std::string name = several ? std::string(stem).append("-").append(robot) : stem;
      sim::World world = import.world.world();
      world.name = name;
      const int goals = static_cast<int>(world.goals.size());
      result.worlds.push_back(ScenarioWorld{name, std::move(world), goals});
    }
  }
  return result;
}

}  // namespace ifar::scenarios
