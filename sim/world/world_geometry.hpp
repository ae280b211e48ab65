#pragma once
// Geometric questions about a world's entities that loaders, validation, generators and rendering share.

#include "common/geometry/polygon.hpp"
#include "common/vehicle.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim {

/// The object's outline placed at its pose, in world coordinates.
geometry::Polygon placedOutline(const MovableObject& object);
/// The object's outline placed at `pose` (where the physics or a run has moved it), in world coordinates.
geometry::Polygon placedOutline(const MovableObject& object, const geometry::Pose2& pose);

/// The Coulomb force (N) needed to slide the object over the ground: friction x mass x g.
double slidingForce(const MovableObject& object);

/// True when the vehicle's largest push force exceeds the force needed to slide the object.
bool isPushable(const MovableObject& object, const common::VehicleSettings& vehicle);

/// Sets world.bounds_min/bounds_max to the axis-aligned box around every obstacle, object, the start and
/// the goals. An empty world gets the box around the start.
void updateBounds(World& world);

/// True when the interiors of the two polygons overlap with positive area; touching along an edge or at a
/// vertex does not count (a box may stand against a wall).
bool interiorsOverlap(const geometry::Polygon& first, const geometry::Polygon& second);

}  // namespace ifar::sim
