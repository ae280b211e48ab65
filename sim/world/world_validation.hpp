#pragma once
// Checks that a world is physically sensible before physics, lidar or the planner see it. Each problem
// names the entity ("obstacle 'wall_3'", "object 'box_1' (id 4)", "start", "goal 'goal_0'") and what is
// wrong, so a message can point a person at the line to fix.

#include <optional>
#include <string>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim {

struct WorldProblem {
  std::string entity;   // e.g. "object 'box_1' (id 4)"
  std::string problem;  // e.g. "overlaps obstacle 'wall_2'"
};

/// What is wrong with a polygon on its own: fewer than 3 vertices (open), repeated vertices, zero area
/// (degenerate), self-intersection, non-finite coordinates. Empty when it is a simple polygon.
std::optional<std::string> polygonProblem(const geometry::Polygon& polygon);

/// Every problem in the world: bad polygons; movable objects with non-positive mass or height, negative
/// friction, reflectivity outside 0..1, duplicate or non-positive ids; objects overlapping a static obstacle
/// or another object; a start inside an obstacle or object; a goal inside a static obstacle. Empty = valid.
std::vector<WorldProblem> findWorldProblems(const World& world);

/// "<source>: <entity>: <problem>" for the first problem, with a count of further ones.
std::string describeProblems(const std::string& source, const std::vector<WorldProblem>& problems);

}  // namespace ifar::sim
