#pragma once
// Seeded generators for the paper's kinds of place. The same kind and seed give the same world on every
// run and platform; different seeds give different layouts. Every generated world passes validation.
//
// - Room: 32 m x 32 m, a partition with a doorway (the short cut) and a wide opening (the long way),
//   static furniture. RoomObjects: the same room plus movable boxes, one in the doorway.
// - Office: rooms either side of a corridor, doors, a corridor fire door; start and goal in rooms at
//   opposite ends (paths about 50 m); boxes in some doors and rooms.
// - Tunnel: a 330 m x 270 m network of 4 m tunnels through rock; the goal is the junction whose shortest
//   route from the start is nearest 450 m; crates block some tunnels on that route.
// - DemoRoom: RoomObjects with a fixed layout: the goal is behind a light box in the doorway.
// - BlockedOffice, BlockedTunnel: the paper's kind of place for pushing, where light objects block the
//   doors and tunnels on the short way, so that never pushing costs a long way round: the office with
//   every door box light, boxes in the start's and the goal's room's corridor doors and the side doors
//   deep in the rooms; the tunnel with every crate on the route light, on the tunnels whose way round is
//   longest.
// Light objects slide with well under the vehicle's maximum push; heavy ones cannot be pushed.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/world/world_result.hpp"

namespace ifar::sim {

enum class WorldKind { Room, RoomObjects, Office, Tunnel, DemoRoom, BlockedOffice, BlockedTunnel };

/// Every kind, in the order above.
const std::vector<WorldKind>& allWorldKinds();

/// "room", "room_objects", "office", "tunnel", "demo_room", "blocked_office", "blocked_tunnel".
std::optional<WorldKind> parseWorldKind(const std::string& text);
std::string worldKindName(WorldKind kind);

World generateRoom(std::uint64_t seed, bool with_objects);
World generateDemoRoom();
/// Which boxes an office's doors get: a mix of light and too heavy (Office), or light ones, in the start's
/// and the goal's room's doors too (BlockedOffice).
enum class OfficeObjects { Mixed, LightBlocked };
World generateOffice(std::uint64_t seed);
World generateOffice(std::uint64_t seed, OfficeObjects objects);
/// Which crates a tunnel's route gets: up to three, one too heavy where a way round exists (Tunnel), or up
/// to four light ones on the tunnels whose way round is longest (BlockedTunnel).
enum class TunnelCrates { Mixed, LightOnLongestDetours };
World generateTunnel(std::uint64_t seed);
World generateTunnel(std::uint64_t seed, TunnelCrates crates);

/// Generates and validates (a generator bug becomes an error naming the generator and seed).
WorldResult generateWorld(WorldKind kind, std::uint64_t seed);

}  // namespace ifar::sim
