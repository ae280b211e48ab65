#pragma once
// Small worlds built in code: for tests, benchmarks and the daemon's --builtin flag when no world file
// is at hand.

#include <cstdint>
#include <string>

#include "sim/world/world.hpp"

namespace ifar::sim {

/// A square room of `size_m` with 0.2 m thick, 2 m high walls, the vehicle at (2, size/2) facing +x.
World builtinRoom(double size_m = 12.0);

/// The room with one box (`box_side_m` square, `box_mass_kg`, ground friction `box_friction`, id 1)
/// centred `box_distance_m` ahead of the vehicle's start.
World builtinPushRoom(double box_mass_kg, double box_friction = 0.5, double box_side_m = 0.6,
                      double box_distance_m = 1.5, double room_size_m = 12.0);

/// A tunnel-like network for benchmarks: a `width_m` x `height_m` area split by a seeded maze of
/// corridors (walls 0.3 m thick, 3 m high); hundreds of walls in the default size.
World builtinTunnelNetwork(std::uint64_t seed = 7, double width_m = 330.0, double height_m = 270.0,
                           double corridor_m = 15.0);

/// Looks a builtin up by name ("room", "push_light", "push_heavy", "tunnel"); false when unknown.
bool builtinWorldByName(const std::string& name, World& world);

}  // namespace ifar::sim
