#pragma once
// A small valid world shared by the world tests.

#include "sim/world/world.hpp"
#include "sim/world/world_geometry.hpp"

namespace ifar::sim::testing {

inline geometry::Polygon rectangle(double x0, double y0, double x1, double y1)
{
  return {geometry::Point(x0, y0), geometry::Point(x1, y0), geometry::Point(x1, y1), geometry::Point(x0, y1)};
}

/// A 10 m x 8 m room with a box and a goal.
inline World smallRoom()
{
  World world;
  world.name = "small room";
  world.source = "test";
  world.obstacles.push_back({"wall_south", rectangle(0, 0, 10, 0.2), 2.0, 0.2});
  world.obstacles.push_back({"wall_north", rectangle(0, 7.8, 10, 8), 2.5, 0.1});
  world.obstacles.push_back(
      {"pillar", {geometry::Point(5, 3), geometry::Point(6, 3), geometry::Point(5.5, 4)}, 3, 0.3});
  MovableObject box;
  box.id = 7;
  box.name = "box_7";
  box.outline = rectangle(-0.4, -0.3, 0.4, 0.3);
  box.pose = {3.0, 5.0, 0.3};
  box.mass_kg = 25.5;
  box.ground_friction = 0.45;
  box.reflectivity = 0.95;
  box.height_m = 0.8;
  world.objects.push_back(box);
  world.start = {1.0, 1.0, 1.0471975511965976};
  world.goals.push_back({"goal_0", geometry::Point(9.0, 6.5)});
  world.goals.push_back({"goal_1", geometry::Point(2.0, 6.5)});
  updateBounds(world);
  return world;
}

}  // namespace ifar::sim::testing
