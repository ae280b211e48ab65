#include "sim/generators/generators.hpp"

#include "sim/world/world_validation.hpp"

namespace ifar::sim {

std::optional<WorldKind> parseWorldKind(const std::string& text)
{
  for (const WorldKind kind :
       {WorldKind::Room, WorldKind::RoomObjects, WorldKind::Office, WorldKind::Tunnel, WorldKind::DemoRoom}) {
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
  }
  const auto problems = findWorldProblems(world);
  if (!problems.empty()) {
    return WorldResult::failure(describeProblems(world.source, problems));
  }
  return WorldResult::success(std::move(world));
}

}  // namespace ifar::sim
