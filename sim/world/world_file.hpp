#pragma once
// World files: YAML in the format of docs/worlds.md, read strictly (unknown keys and units are errors)
// and validated, so a bad file is reported with file, entity and problem before anything runs.

#include <string>

#include "sim/world/world.hpp"
#include "sim/world/world_result.hpp"

namespace ifar::sim {

/// Reads and validates a world file. The error names the file, the entity and the problem.
WorldResult loadWorldFile(const std::string& path);

/// Parses and validates world YAML; `source_name` stands in for the file name in messages.
WorldResult parseWorld(const std::string& text, const std::string& source_name);

/// The world as YAML (units m, headings in degrees, numbers in shortest round-trip form), such that
/// parseWorld(formatWorld(w)) reproduces w.
std::string formatWorld(const World& world);

/// Writes formatWorld(world) to `path`. Returns an empty string on success, else the error.
std::string saveWorldFile(const World& world, const std::string& path);

}  // namespace ifar::sim
