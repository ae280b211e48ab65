#include "sim/generators/generators.hpp"

#include "sim/world/world_validation.hpp"

namespace ifar::sim {

const std::vector<WorldKind>& allWorldKinds()
{
  static const std::vector<WorldKind> kinds{
      WorldKind::Room,     WorldKind::RoomObjects,   WorldKind::Office,       WorldKind::Tunnel,
      WorldKind::DemoRoom, WorldKind::BlockedOffice, WorldKind::BlockedTunnel};
  return kinds;
}

std::optional<WorldKind> parseWorldKind(const std::string& text)
{
  for (const WorldKind kind : allWorldKinds()) {
    if (worldKindName(kind) == text) {
      return kind;
    }
  }
  return std::nullopt;
}

std::string worldKindName(WorldKind kind)
{
  switch (kind) {
    case WorldKind::Room:
      return "room";
    case WorldKind::RoomObjects:
      return "room_objects";
    case WorldKind::Office:
      return "office";
    case WorldKind::Tunnel:
      return "tunnel";
    case WorldKind::DemoRoom:
      return "demo_room";
    case WorldKind::BlockedOffice:
      return "blocked_office";
    case WorldKind::BlockedTunnel:
      return "blocked_tunnel";
  }
  return "unknown";
}

WorldResult generateWorld(WorldKind kind, std::uint64_t seed)
{
  World world;
  switch (kind) {
    case WorldKind::Room:
      world = generateRoom(seed, false);
      break;
    case WorldKind::RoomObjects:
      world = generateRoom(seed, true);
      break;
    case WorldKind::Office:
      world = generateOffice(seed);
      break;
    case WorldKind::Tunnel:
      world = generateTunnel(seed);
      break;
    case WorldKind::DemoRoom:
      world = generateDemoRoom();
      break;
    case WorldKind::BlockedOffice:
      world = generateOffice(seed, OfficeObjects::LightBlocked);
      break;
    case WorldKind::BlockedTunnel:
      world = generateTunnel(seed, TunnelCrates::LightOnLongestDetours);
      break;
  }
  const auto problems = findWorldProblems(world);
  if (!problems.empty()) {
    return WorldResult::failure(describeProblems(world.source, problems));
  }
  return WorldResult::success(std::move(world));
}

}  // namespace ifar::sim
