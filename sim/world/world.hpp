#pragma once
// The simulated world: what a world file (YAML), an importer or a generator produces and what physics,
// lidar and rendering consume. Plain values in SI units, world frame, z up.

#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"

namespace ifar::sim {

/// A static obstacle: an extruded polygon (walls, pillars, furniture bolted down).
struct StaticObstacle {
  std::string name;           // for messages, e.g. "wall_3"
  geometry::Polygon outline;  // counter-clockwise, metres
  double height_m = 2.0;      // extrusion height above ground
  double reflectivity = 0.2;  // 0..1, what the lidar reports scaled to 0..255 (untagged surfaces are low)
};

/// A body the vehicle can push (or try to).
struct MovableObject {
  std::int64_t id = 0;  // unique within the world, > 0
  std::string name;
  geometry::Polygon outline;  // counter-clockwise, in the object's body frame (centroid at origin)
  geometry::Pose2 pose;       // initial pose of the body frame in the world
  double height_m = 1.0;
  double mass_kg = 20.0;
  double ground_friction = 0.5;  // Coulomb coefficient against the ground
  double reflectivity = 0.9;     // retro-reflective tag: high
};

struct Goal {
  std::string name;
  geometry::Point position;
};

struct World {
  std::string name;
  std::string source;          // file or generator it came from, for messages
  geometry::Point bounds_min;  // axis-aligned extent of everything, metres
  geometry::Point bounds_max;
  std::vector<StaticObstacle> obstacles;
  std::vector<MovableObject> objects;
  geometry::Pose2 start;  // vehicle start pose
  std::vector<Goal> goals;
};

}  // namespace ifar::sim
