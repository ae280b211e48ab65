#pragma once
// Small hand-made worlds for the scenario tests.

#include "sim/world/world.hpp"
#include "sim/world/world_geometry.hpp"

namespace ifar::scenarios::test {

inline geometry::Polygon box(double x0, double y0, double x1, double y1)
{
  return {geometry::Point(x0, y0), geometry::Point(x1, y0), geometry::Point(x1, y1), geometry::Point(x0, y1)};
}

/// Two 15 m x 10 m rooms side by side; the only way between them is a 1.2 m door at (15, 5), closed by a
/// 0.3 m x 1.1 m box (light: 20 kg, or heavy: 300 kg at friction 0.7, over 2,000 N to slide). The start
/// (5, 5) and goal (25, 5) are 20 m apart in a straight line.
inline sim::World twoRoomsWithDoorBox(bool heavy)
{
  sim::World world;
  world.name = heavy ? "two_rooms_heavy" : "two_rooms_light";
  world.source = "test";
  world.obstacles = {
      {"south", box(0.0, 0.0, 30.0, 0.2), 2.0, 0.2},  {"north", box(0.0, 9.8, 30.0, 10.0), 2.0, 0.2},
      {"west", box(0.0, 0.2, 0.2, 9.8), 2.0, 0.2},    {"east", box(29.8, 0.2, 30.0, 9.8), 2.0, 0.2},
      {"lower", box(14.9, 0.2, 15.1, 4.4), 2.0, 0.2}, {"upper", box(14.9, 5.6, 15.1, 9.8), 2.0, 0.2},
  };
  sim::MovableObject door_box;
  door_box.id = 1;
  door_box.name = "door_box";
  door_box.outline = box(-0.15, -0.55, 0.15, 0.55);
  door_box.pose = {15.0, 5.0, 0.0};
  door_box.mass_kg = heavy ? 300.0 : 20.0;
  door_box.ground_friction = heavy ? 0.7 : 0.5;
  world.objects.push_back(door_box);
  world.start = {5.0, 5.0, 0.0};
  world.goals = {{"goal_0", geometry::Point(25.0, 5.0)}};
  sim::updateBounds(world);
  return world;
}

}  // namespace ifar::scenarios::test
