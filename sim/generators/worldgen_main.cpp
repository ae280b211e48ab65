// ifar-worldgen: writes a generated world file (docs/worlds.md).

#include <cstdint>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "sim/generators/generators.hpp"
#include "sim/world/world_file.hpp"

int main(int argc, char** argv)
{
  CLI::App app(
      "Generate a seeded simulator world (room, room_objects, office, tunnel, demo_room,\n"
      "blocked_office, blocked_tunnel) as YAML",
      "ifar-worldgen");
  std::string kind_text;
  std::uint64_t seed = 1;
  std::string out;
  app.add_option("--kind", kind_text,
                 "room | room_objects | office | tunnel | demo_room | blocked_office | blocked_tunnel")
      ->required();
  app.add_option("--seed", seed, "random seed: the same seed gives the same world")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  app.add_option("--out", out, "world file to write (default: standard output)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  const auto kind = ifar::sim::parseWorldKind(kind_text);
  if (!kind) {
    std::cerr
        << "error: --kind: unknown kind '" << kind_text
        << "' (expected room, room_objects, office, tunnel, demo_room, blocked_office or blocked_tunnel)\n";
    return ifar::common::kBadInputExitCode;
  }
  const auto result = ifar::sim::generateWorld(*kind, seed);
  if (!result.ok()) {
    std::cerr << "error: " << result.error() << "\n";
    return 1;
  }
  if (out.empty()) {
    std::cout << ifar::sim::formatWorld(result.world());
    return 0;
  }
  const auto error = ifar::sim::saveWorldFile(result.world(), out);
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return ifar::common::kOutputFailedExitCode;
  }
  std::cerr << "wrote " << out << ": " << result.world().obstacles.size() << " obstacles, "
            << result.world().objects.size() << " movable objects, " << result.world().goals.size()
            << " goals\n";
  return 0;
}
