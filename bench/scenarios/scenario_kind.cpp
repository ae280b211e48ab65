#include "bench/scenarios/scenario_kind.hpp"

namespace ifar::scenarios {

std::string kindName(ScenarioKind kind)
{
  switch (kind) {
    case ScenarioKind::Room:
      return "room";
    case ScenarioKind::RoomObjects:
      return "room_objects";
    case ScenarioKind::Office:
      return "office";
    case ScenarioKind::Willow:
      return "willow";
    case ScenarioKind::Tunnel:
      return "tunnel";
    case ScenarioKind::BlockedOffice:
      return "blocked_office";
    case ScenarioKind::BlockedTunnel:
      return "blocked_tunnel";
    case ScenarioKind::Namosim:
      return "namosim";
    case ScenarioKind::WillowPairs:
      return "willow_pairs";
  }
  return "unknown";
}

std::optional<ScenarioKind> parseKind(const std::string& text)
{
  for (const ScenarioKind kind : allKinds()) {
    if (kindName(kind) == text) {
      return kind;
    }
  }
  return std::nullopt;
}

const std::vector<ScenarioKind>& allKinds()
{
  static const std::vector<ScenarioKind> kinds{
      ScenarioKind::Room,          ScenarioKind::RoomObjects, ScenarioKind::Office,
      ScenarioKind::Willow,        ScenarioKind::Tunnel,      ScenarioKind::BlockedOffice,
      ScenarioKind::BlockedTunnel, ScenarioKind::Namosim,     ScenarioKind::WillowPairs};
  return kinds;
}

double minimumOptimalLength(ScenarioKind kind)
{
  switch (kind) {
    case ScenarioKind::Namosim:
      return 0.0;
    case ScenarioKind::WillowPairs:
      return 10.0;
    case ScenarioKind::Room:
    case ScenarioKind::RoomObjects:
      return 15.0;
    case ScenarioKind::Willow:
    case ScenarioKind::BlockedOffice:
      return 40.0;
    case ScenarioKind::Office:
    case ScenarioKind::Tunnel:
    case ScenarioKind::BlockedTunnel:
      return 80.0;
  }
  return 80.0;
}

}  // namespace ifar::scenarios
