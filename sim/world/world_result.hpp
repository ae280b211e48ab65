#pragma once
// The outcome of reading, importing or generating a world: the world, or one message naming the source,
// the entity and the problem. Bad input is an expected outcome, so it is a value, not an exception.

#include <optional>
#include <string>
#include <utility>

#include "sim/world/world.hpp"

namespace ifar::sim {

class WorldResult {
 public:
  static WorldResult success(World world) { return WorldResult(std::move(world), {}); }
  /// `message` reads "<source>: <entity>: <problem>".
  static WorldResult failure(std::string message) { return WorldResult(std::nullopt, std::move(message)); }

  bool ok() const { return world_.has_value(); }
  /// Precondition: ok().
  const World& world() const { return *world_; }
  World& world() { return *world_; }
  /// Empty when ok().
  const std::string& error() const { return error_; }

 private:
  WorldResult(std::optional<World> world, std::string error)
      : world_(std::move(world)), error_(std::move(error))
  {
  }
  std::optional<World> world_;
  std::string error_;
};

}  // namespace ifar::sim
