#pragma once
// Local-layer scenes for interaction tests and benchmarks. Polygons are already inflated by the
// vehicle's half width (0.35 m), as perception delivers them.

#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/interaction/connectivity.hpp"

namespace ifar::interaction::test {

inline geometry::Polygon rectangle(double min_x, double min_y, double max_x, double max_y)
{
  return {geometry::Point(min_x, min_y), geometry::Point(max_x, min_y), geometry::Point(max_x, max_y),
          geometry::Point(min_x, max_y)};
}

/// A wall along x = 0 with a door; a box (real 0.5 m x 0.9 m) stands in the doorway.
inline LocalScene doorwayScene()
{
  LocalScene scene;
  scene.background = {rectangle(-0.5, 0.6, 0.5, 5.0), rectangle(-0.5, -5.0, 0.5, -0.6)};
  scene.movable = {rectangle(-0.6, -0.8, 0.6, 0.8)};
  return scene;
}

/// The doorway with a wall 1.8 m (real) beyond the door: a straight push from the left runs into it,
/// so the box has to be turned aside.
inline LocalScene doorwayWithWallBehindScene()
{
  LocalScene scene = doorwayScene();
  scene.background.push_back(rectangle(1.45, -1.0, 2.5, 1.0));
  return scene;
}

/// The doorway with a wall 1.8 m (real) beyond the door seen as the layer sees a wall by one face: one
/// 0.15 m cell (x from 1.8 to 1.95), inflated over whole cells to a rectangle 0.75 m wide.
inline LocalScene doorwayWithThinWallBehindScene()
{
  LocalScene scene = doorwayScene();
  scene.background.push_back(rectangle(1.5, -1.0, 2.25, 1.0));
  return scene;
}

/// The doorway with a wall 1.6 m (real) beyond the door: the box has to be pushed through, then the
/// vehicle drives round it and pushes it sideways (a contact switch).
inline LocalScene doorwayWithNearWallScene()
{
  LocalScene scene = doorwayScene();
  scene.background.push_back(rectangle(1.25, -1.0, 2.25, 1.0));
  return scene;
}

/// A corridor along x (real free band 0 < y < 2) with a stem going down (real -1 < x < 1); a box
/// (real 1.2 m x 1.0 m) in the junction blocks all three arms.
inline LocalScene tJunctionScene()
{
  LocalScene scene;
  scene.background = {rectangle(-6.35, 1.65, 6.35, 3.35), rectangle(-6.35, -6.35, -0.65, 0.35),
                      rectangle(0.65, -6.35, 6.35, 0.35)};
  scene.movable = {rectangle(-0.95, 0.1, 0.95, 1.8)};
  return scene;
}

/// A corridor along x (real free band 0 < y < 2.5, known 8 m each way) crossed at x = 0 by a wall (real
/// 0.2 m thick) with a 1.2 m fire door; a box (real 0.5 m x 1.1 m) stands in the door. Pushed straight
/// along the corridor it leaves 0.7 m each side: the vehicle's width, no room to drive.
inline LocalScene fireDoorScene()
{
  LocalScene scene;
  scene.background = {rectangle(-8.0, -2.0, 8.0, 0.35), rectangle(-8.0, 2.15, 8.0, 4.0),
                      rectangle(-0.45, 0.35, 0.45, 1.0), rectangle(-0.45, 1.5, 0.45, 2.15)};
  scene.movable = {rectangle(-0.6, 0.35, 0.6, 2.15)};
  return scene;
}

/// The fire door with a side door (real 1.0 < x < 2.2) in the corridor's south wall (real 0.1 m thick)
/// just beyond it, to unseen space: pushed straight east past that door the box still closes the
/// corridor, though the east side of the fire door keeps a way out through the side door.
inline LocalScene fireDoorWithSideDoorScene()
{
  LocalScene scene = fireDoorScene();
  scene.background[0] = rectangle(-8.0, -0.45, 1.35, 0.35);
  scene.background.push_back(rectangle(1.85, -0.45, 8.0, 0.35));
  return scene;
}

/// The fire door with a room along the corridor's north side (wall real 2.5 < y < 2.6), its doors at
/// real -4.8 < x < -3.6 (west of the fire door, beyond the connectivity window but within the push
/// search's surroundings) and 0.6 < x < 1.6 (just east of the fire door): the two sides of the fire door
/// are joined round it through the room, yet a box pushed straight east past the room's east door closes
/// the corridor beyond it.
inline LocalScene fireDoorBesideARoomScene()
{
  LocalScene scene = fireDoorScene();
  scene.background[1] = rectangle(-8.0, 2.15, -4.45, 2.95);
  scene.background.push_back(rectangle(-3.95, 2.15, 0.95, 2.95));
  scene.background.push_back(rectangle(1.25, 2.15, 8.0, 2.95));
  return scene;
}

/// The fire door with a room along the corridor's south side (wall real -0.1 < y < 0, room down to y =
/// -4), its doors at real -4.8 < x < -3.6 and 3.6 < x < 4.8: a box pushed 2 m along the corridor closes
/// it, yet the corridor beyond stays reachable round through the room.
inline LocalScene fireDoorWithALoopRoundItScene()
{
  LocalScene scene = fireDoorScene();
  scene.background[0] = rectangle(-8.35, -0.45, -4.45, 0.35);
  scene.background.push_back(rectangle(-3.95, -0.45, 3.95, 0.35));
  scene.background.push_back(rectangle(4.45, -0.45, 8.35, 0.35));
  scene.background.push_back(rectangle(-8.35, -4.45, 8.35, -3.65));
  return scene;
}

/// A passage (real 1.3 m wide, 0 < y < 6) from a corridor running south (real 4 m wide) to a room (real
/// 10 m x 5 m) with a corridor on north; a box (real 1.0 m x 0.5 m) plugs its south mouth. Only pushed
/// the whole 6 m through and out into the room does it leave the way on open.
inline LocalScene pluggedPassageScene()
{
  const auto inflated = [](double min_x, double min_y, double max_x, double max_y) {
    return rectangle(min_x - 0.35, min_y - 0.35, max_x + 0.35, max_y + 0.35);
  };
  LocalScene scene;
  scene.background = {inflated(-10.0, -30.0, -2.0, 0.0), inflated(2.0, -30.0, 10.0, 0.0),
                      inflated(-10.0, 0.0, -0.65, 6.0),  inflated(0.65, 0.0, 10.0, 6.0),
                      inflated(-10.0, 6.0, -5.0, 11.0),  inflated(5.0, 6.0, 10.0, 11.0),
                      inflated(-10.0, 11.0, -2.0, 30.0), inflated(2.0, 11.0, 10.0, 30.0)};
  scene.movable = {inflated(-0.5, 0.3, 0.5, 0.8)};
  return scene;
}

/// The fire door with its box seen only as its west face (real 1.1 m long, 0.1 m deep, 5 cm to each
/// side of the door).
inline LocalScene faceOnlyFireDoorScene()
{
  LocalScene scene = fireDoorScene();
  scene.movable = {rectangle(-0.25 - 0.35, 0.35, -0.15 + 0.35, 2.15)};
  return scene;
}

/// The fire door's box seen only as its west face, in a door whose wall is 3 m thick (real -0.1 < x <
/// 2.9): a passage 1.2 m wide and 3 m long across the corridor.
inline LocalScene faceOnlyInALongDoorScene()
{
  LocalScene scene = faceOnlyFireDoorScene();
  scene.background[2] = rectangle(-0.45, 0.35, 3.25, 1.0);
  scene.background[3] = rectangle(-0.45, 1.5, 3.25, 2.15);
  return scene;
}

/// The doorway's box seen only by its west face (0.1 m of its real 0.5 m depth), with a wall (real 1.7 <
/// x < 2.05, -0.65 < y < 0.65) beyond the door: pushed straight east as far as the face alone allows, the
/// real box runs into it.
inline LocalScene faceOnlyDoorwayWithWallBehindScene()
{
  LocalScene scene = doorwayScene();
  scene.movable = {rectangle(-0.25 - 0.35, -0.45 - 0.35, -0.15 + 0.35, 0.45 + 0.35)};
  scene.background.push_back(rectangle(1.7 - 0.35, -0.65 - 0.35, 2.05 + 0.35, 0.65 + 0.35));
  return scene;
}

/// faceOnlyDoorwayWithWallBehindScene's walls as they really are (not inflated).
inline std::vector<geometry::Polygon> faceOnlyDoorwayWithWallBehindRealWalls()
{
  return {rectangle(-0.15, 0.95, 0.15, 4.65), rectangle(-0.15, -4.65, 0.15, -0.95),
          rectangle(1.7, -0.65, 2.05, 0.65)};
}

/// A tunnel 4 m wide (x from -2 to 2) leaving a T-junction (y from 2 to 6) southward; a bar of 3.6 m x
/// 1.2 m (real) fills it just short of the junction. With `junction_beyond`, a crossing tunnel 38 m
/// further south (y from -40 to -36) and the tunnel on beyond it; without, the tunnel ends there.
inline LocalScene barInATunnelScene(bool junction_beyond)
{
  const auto inflated = [](double min_x, double min_y, double max_x, double max_y) {
    return rectangle(min_x - 0.35, min_y - 0.35, max_x + 0.35, max_y + 0.35);
  };
  LocalScene scene;
  scene.background = {inflated(-15.0, 6.0, 15.0, 10.0), inflated(-15.0, -36.0, -2.0, 2.0),
                      inflated(2.0, -36.0, 15.0, 2.0)};
  if (junction_beyond) {
    scene.background.push_back(inflated(-15.0, -60.0, -2.0, -40.0));
    scene.background.push_back(inflated(2.0, -60.0, 15.0, -40.0));
  } else {
    scene.background.push_back(inflated(-15.0, -40.0, 15.0, -36.0));
  }
  scene.movable = {inflated(-1.8, 0.2, 1.8, 1.4)};
  return scene;
}

}  // namespace ifar::interaction::test
