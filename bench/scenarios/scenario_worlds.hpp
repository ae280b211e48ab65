#pragma once
// The worlds of each scenario kind. Room and RoomObjects use the room generator; Tunnel the tunnel
// generator (330 m x 270 m); Office generated offices: the generator's office is 48 m x 24 m, too small
// for tasks longer than 80 m, so two generated offices are joined end to end along their corridors
// (96 m x 24 m). Willow is the Willow Garage plan with movable boxes placed in its doors and corridors
// by seed. The generalization kinds: namosim takes every scenario SVG of a folder (namosim_worlds.hpp);
// willow_pairs the full Willow Garage map as it is, without objects (its tasks are drawn pairs,
// clear_pairs.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "bench/scenarios/scenario_kind.hpp"
#include "sim/world/world.hpp"
#include "sim/world/world_result.hpp"

namespace ifar::scenarios {

struct ScenarioWorld {
  std::string name;  // e.g. "room-1", "willow", "office2x-3+4", "tunnel-1"
  sim::World world;
  int task_quota = 0;  // how many of the kind's tasks this world should give
};

struct WorldSetSettings {
  std::uint64_t seed = 1;
  int tasks = 10;                // tasks of the kind, shared out over its worlds
  std::string willow_map;        // map_server .yaml of the Willow Garage plan; empty or missing: kind skipped
  std::string namosim_folder;    // namosim scenario SVGs; empty, missing or without one: kind skipped
  double vehicle_width_m = 0.7;  // a namosim robot is scaled to this width
};

struct WorldSetResult {
  std::vector<ScenarioWorld> worlds;
  std::string error;               // empty on success
  std::vector<std::string> notes;  // e.g. "willow map ... absent: kind skipped" (no worlds, not an error)
  bool ok() const { return error.empty(); }
};

/// The worlds of one kind for a seed; the task quotas add up to settings.tasks.
WorldSetResult scenarioWorlds(ScenarioKind kind, const WorldSetSettings& settings);

/// Joins two generated offices (ifar::sim::generateOffice) end to end: `east` is shifted right by the
/// width of `west`, the outer walls where they meet get an opening across the corridor, and east's
/// object ids follow west's. Start from `west`, goal from `east`. An error when the layouts do not look
/// like the generator's (e.g. the generator changed).
sim::WorldResult joinOfficesAlongCorridor(const sim::World& west, const sim::World& east);

/// The Willow Garage plan imported as a world, with movable boxes placed by `seed`: boxes that close
/// door-like gaps (0.7-1.3 m wide) and boxes standing against one side of corridors (1.6-3.0 m wide,
/// leaving 1.2 m or more beside them). Most are light
/// (pushable); about one in five is too heavy for the vehicle.
sim::WorldResult willowWithObjects(const std::string& map_yaml, std::uint64_t seed);

}  // namespace ifar::scenarios
