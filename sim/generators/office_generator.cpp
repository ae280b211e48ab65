#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/generators/generators.hpp"
#include "sim/generators/world_builder.hpp"

namespace ifar::sim {
namespace {

constexpr double kWidth = 48.0;
constexpr double kHeight = 24.0;
constexpr double kBlockedHeight = 30.0;  // with the doors blocked: deeper rooms, longer ways round
constexpr double kWall = 0.2;
constexpr double kCorridorWidth = 2.5;  // the corridor runs along the middle
constexpr double kDoor = 1.0;
constexpr double kFireDoor = 1.2;

double tenth(double value)
{
  return std::round(value * 10.0) / 10.0;
}

/// Wall pieces along x at [y0, y1] from x_begin to x_end, leaving gaps of `gap` around each door centre.
void wallWithDoorsAlongX(WorldBuilder& builder, double x_begin, double x_end, double y0, double y1,
                         const std::vector<double>& doors, double gap)
{
  double from = x_begin;
  for (const double door : doors) {
    builder.addRectangle("wall", {from, y0, door - 0.5 * gap, y1});
    from = door + 0.5 * gap;
  }
  builder.addRectangle("wall", {from, y0, x_end, y1});
}

void wallWithDoorsAlongY(WorldBuilder& builder, double y_begin, double y_end, double x0, double x1,
                         const std::vector<double>& doors, double gap)
{
  double from = y_begin;
  for (const double door : doors) {
    builder.addRectangle("wall", {x0, from, x1, door - 0.5 * gap});
    from = door + 0.5 * gap;
  }
  builder.addRectangle("wall", {x0, from, x1, y_end});
}

struct Row {
  double y0;  // room interior between y0 and y1
  double y1;
};

}  // namespace

World generateOffice(std::uint64_t seed)
{
  return generateOffice(seed, OfficeObjects::Mixed);
}

World generateOffice(std::uint64_t seed, OfficeObjects objects)
{
  const bool light_blocked = objects == OfficeObjects::LightBlocked;
  SeededRandom random(seed);
  WorldBuilder builder(
      light_blocked ? "blocked_office" : "office",
      std::string(light_blocked ? "generator blocked_office seed " : "generator office seed ") +
          std::to_string(seed));

  // Room boundaries along x, shared by both rows.
  std::vector<double> bounds{0.0};
  while (kWidth - bounds.back() > 13.0) {
    bounds.push_back(tenth(bounds.back() + random.uniform(5.5, 8.0)));
  }
  bounds.push_back(kWidth);
  const std::size_t rooms = bounds.size() - 1;
  // Fire doors stand at bounds[index] for these indices: one in the middle, or with the doors blocked by
  // light boxes two, at a third and two thirds of the corridor.
  std::vector<std::size_t> fire_indices{rooms / 2};
  if (light_blocked && rooms >= 6) {
    fire_indices = {rooms / 3, (2 * rooms) / 3};
  }
  const auto fire_door_at = [&fire_indices](std::size_t index) {
    return std::find(fire_indices.begin(), fire_indices.end(), index) != fire_indices.end();
  };

  const double height = light_blocked ? kBlockedHeight : kHeight;
  const double corridor_low = 0.5 * (height - kCorridorWidth);  // corridor between these y
  const double corridor_high = 0.5 * (height + kCorridorWidth);
  builder.addRectangle("wall", {0.0, 0.0, kWidth, kWall});
  builder.addRectangle("wall", {0.0, height - kWall, kWidth, height});
  builder.addRectangle("wall", {0.0, kWall, kWall, height - kWall});
  builder.addRectangle("wall", {kWidth - kWall, kWall, kWidth, height - kWall});

  const Row rows[2] = {{kWall, corridor_low - kWall}, {corridor_high + kWall, height - kWall}};
  std::vector<Box2> keep_clear;
  std::vector<std::pair<geometry::Point, bool>> blocked_doors;  // centre, door in a wall along y
  std::vector<geometry::Point> end_room_doors;                  // the start's and the goal's room's
  for (int row = 0; row < 2; ++row) {
    // Corridor doors, one per room.
    std::vector<double> doors;
    for (std::size_t room = 0; room < rooms; ++room) {
      doors.push_back(tenth(random.uniform(bounds[room] + 1.2, bounds[room + 1] - 1.2)));
      const double door_y = row == 0 ? corridor_low : corridor_high;
      keep_clear.push_back({doors.back() - 1.2, door_y - 1.8, doors.back() + 1.2, door_y + 1.8});
      if ((row == 0 && room == 0) || (row == 1 && room + 1 == rooms)) {
        end_room_doors.emplace_back(doors.back(),
                                    0.5 * (door_y + (row == 0 ? door_y - kWall : door_y + kWall)));
      }
    }
    const double wall_y0 = row == 0 ? corridor_low - kWall : corridor_high;
    wallWithDoorsAlongX(builder, kWall, kWidth - kWall, wall_y0, wall_y0 + kWall, doors, kDoor);

    // Walls between neighbouring rooms; some with a door, the ones beside the fire door always, so the
    // way round through the rooms exists when the fire door's box is too heavy. With the doors blocked
    // by light boxes, the start's and the goal's room have a side door too, and every side door stands
    // deep in its room, by the outer wall: going round a box then costs twice the room's depth.
    for (std::size_t index = 1; index < rooms; ++index) {
      const double x = bounds[index];
      std::vector<double> side_doors;
      const bool end_room = (row == 0 && index == 1) || (row == 1 && index + 1 == rooms);
      const bool forced = (row == 0 && fire_door_at(index)) || (light_blocked && end_room);
      // With the doors blocked by light boxes only the forced side doors exist: deep side doors in every
      // wall would line up into a way along the rooms' far ends as short as the corridor.
      if (forced || (!light_blocked && random.chance(0.5))) {
        const double deep_low = row == 0 ? rows[row].y0 + 0.9 : rows[row].y1 - 1.5;
        side_doors.push_back(light_blocked ? tenth(random.uniform(deep_low, deep_low + 0.6))
                                           : tenth(random.uniform(rows[row].y0 + 1.5, rows[row].y1 - 1.5)));
        keep_clear.push_back({x - 1.5, side_doors.back() - 1.2, x + 1.5, side_doors.back() + 1.2});
        if (!forced && random.chance(0.5)) {
          blocked_doors.push_back({geometry::Point(x, side_doors.back()), true});
        }
      }
      wallWithDoorsAlongY(builder, rows[row].y0, rows[row].y1, x - 0.5 * kWall, x + 0.5 * kWall, side_doors,
                          kDoor);
    }
  }

  // The corridor's fire doors: the short way along the corridor.
  const double corridor_mid = 0.5 * (corridor_low + corridor_high);
  for (const std::size_t fire_index : fire_indices) {
    const double fire_x = bounds[fire_index];
    wallWithDoorsAlongY(builder, corridor_low, corridor_high, fire_x - 0.5 * kWall, fire_x + 0.5 * kWall,
                        {corridor_mid}, kFireDoor);
    keep_clear.push_back({fire_x - 2.0, corridor_low, fire_x + 2.0, corridor_high});
  }

  // Start and goal in the middle of their rooms; with the doors blocked by light boxes, 2.5 m inside
  // the corridor door instead, so that the way round by the deep side door is as long as the room is deep.
  const double start_y = light_blocked ? rows[0].y1 - 2.5 : 0.5 * (rows[0].y0 + rows[0].y1);
  const double goal_y = light_blocked ? rows[1].y0 + 2.5 : 0.5 * (rows[1].y0 + rows[1].y1);
  const geometry::Pose2 start{tenth(0.5 * (bounds[0] + bounds[1])), tenth(start_y), 0.0};
  const geometry::Point goal(tenth(0.5 * (bounds[rooms - 1] + bounds[rooms])), tenth(goal_y));
  builder.setStart(start);
  builder.addGoal(goal);

  // Boxes that close doors: the fire door's is heavy for odd seeds and light for even ones, so any two
  // consecutive seeds hold both cases (a coin can leave a run of seeds all heavy, and then none of those
  // offices has a corridor worth pushing through); room doors' alternate. The coin is still drawn so every
  // seed's other boxes stay where they were.
  // With the doors blocked by light boxes every door box is light, and the start's and the goal's room's
  // corridor doors hold one each: never pushing costs a way round at both ends and at each fire door.
  static_cast<void>(random.chance(0.5));
  for (const std::size_t fire_index : fire_indices) {
    builder.addObject(geometry::Point(bounds[fire_index], corridor_mid), 0.5, kFireDoor - 0.1, 0.0,
                      seed % 2 == 1 && !light_blocked ? ObjectWeight::Heavy : ObjectWeight::Light, random);
  }
  for (std::size_t index = 0; index < blocked_doors.size(); ++index) {
    builder.addObject(blocked_doors[index].first, 0.5, kDoor - 0.1, 0.0,
                      index % 2 == 0 && !light_blocked ? ObjectWeight::Heavy : ObjectWeight::Light, random);
  }
  if (light_blocked) {
    for (const geometry::Point& door : end_room_doors) {
      builder.addObject(door, kDoor - 0.1, 0.5, 0.0, ObjectWeight::Light, random);
    }
  }

  // Loose boxes inside rooms, clear of doors, start and goal.
  for (std::size_t room = 0; room < rooms; ++room) {
    for (const Row& row : rows) {
      const int count = random.integer(0, 2);
      for (int placed = 0, tries = 0; placed < count && tries < 50; ++tries) {
        const double size = random.uniform(0.5, 1.0);
        const geometry::Point centre(random.uniform(bounds[room] + 1.0, bounds[room + 1] - 1.0),
                                     random.uniform(row.y0 + 1.0, row.y1 - 1.0));
        const Box2 box{centre.x() - size, centre.y() - size, centre.x() + size, centre.y() + size};
        bool free = !box.contains(start.position(), 1.5) && !box.contains(goal, 1.5);
        for (const auto& zone : keep_clear) {
          free = free && !box.overlaps(zone);
        }
        for (const auto& other : builder.occupied()) {
          free = free && !box.overlaps(other, 0.8);
        }
        if (free) {
          builder.addObject(centre, size, size, random.uniform(-1.5, 1.5),
                            random.chance(0.5) ? ObjectWeight::Light : ObjectWeight::Heavy, random);
          ++placed;
        }
      }
    }
  }
  return builder.build();
}

}  // namespace ifar::sim
