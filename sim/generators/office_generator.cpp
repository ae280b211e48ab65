#include <cmath>
#include <vector>

#include "sim/generators/generators.hpp"
#include "sim/generators/world_builder.hpp"

namespace ifar::sim {
namespace {

constexpr double kWidth = 48.0;
constexpr double kHeight = 24.0;
constexpr double kWall = 0.2;
constexpr double kCorridorLow = 10.75;  // corridor between these y
constexpr double kCorridorHigh = 13.25;
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
  SeededRandom random(seed);
  WorldBuilder builder("office", "generator office seed " + std::to_string(seed));

  // Room boundaries along x, shared by both rows.
  std::vector<double> bounds{0.0};
  while (kWidth - bounds.back() > 13.0) {
    bounds.push_back(tenth(bounds.back() + random.uniform(5.5, 8.0)));
  }
  bounds.push_back(kWidth);
  const std::size_t rooms = bounds.size() - 1;
  const std::size_t fire_index = rooms / 2;  // the fire door stands at bounds[fire_index]

  builder.addRectangle("wall", {0.0, 0.0, kWidth, kWall});
  builder.addRectangle("wall", {0.0, kHeight - kWall, kWidth, kHeight});
  builder.addRectangle("wall", {0.0, kWall, kWall, kHeight - kWall});
  builder.addRectangle("wall", {kWidth - kWall, kWall, kWidth, kHeight - kWall});

  const Row rows[2] = {{kWall, kCorridorLow - kWall}, {kCorridorHigh + kWall, kHeight - kWall}};
  std::vector<Box2> keep_clear;
  std::vector<std::pair<geometry::Point, bool>> blocked_doors;  // centre, door in a wall along y
  for (int row = 0; row < 2; ++row) {
    // Corridor doors, one per room.
    std::vector<double> doors;
    for (std::size_t room = 0; room < rooms; ++room) {
      doors.push_back(tenth(random.uniform(bounds[room] + 1.2, bounds[room + 1] - 1.2)));
      const double door_y = row == 0 ? kCorridorLow : kCorridorHigh;
      keep_clear.push_back({doors.back() - 1.2, door_y - 1.8, doors.back() + 1.2, door_y + 1.8});
    }
    const double wall_y0 = row == 0 ? kCorridorLow - kWall : kCorridorHigh;
    wallWithDoorsAlongX(builder, kWall, kWidth - kWall, wall_y0, wall_y0 + kWall, doors, kDoor);

    // Walls between neighbouring rooms; some with a door, the ones beside the fire door always, so the
    // way round through the rooms exists when the fire door's box is too heavy.
    for (std::size_t index = 1; index < rooms; ++index) {
      const double x = bounds[index];
      std::vector<double> side_doors;
      const bool forced = row == 0 && index == fire_index;
      if (forced || random.chance(0.5)) {
        side_doors.push_back(tenth(random.uniform(rows[row].y0 + 1.5, rows[row].y1 - 1.5)));
        keep_clear.push_back({x - 1.5, side_doors.back() - 1.2, x + 1.5, side_doors.back() + 1.2});
        if (!forced && random.chance(0.5)) {
          blocked_doors.push_back({geometry::Point(x, side_doors.back()), true});
        }
      }
      wallWithDoorsAlongY(builder, rows[row].y0, rows[row].y1, x - 0.5 * kWall, x + 0.5 * kWall, side_doors,
                          kDoor);
    }
  }

  // The corridor's fire door: the short way along the corridor.
  const double fire_x = bounds[fire_index];
  const double corridor_mid = 0.5 * (kCorridorLow + kCorridorHigh);
  wallWithDoorsAlongY(builder, kCorridorLow, kCorridorHigh, fire_x - 0.5 * kWall, fire_x + 0.5 * kWall,
                      {corridor_mid}, kFireDoor);
  keep_clear.push_back({fire_x - 2.0, kCorridorLow, fire_x + 2.0, kCorridorHigh});

  const geometry::Pose2 start{tenth(0.5 * (bounds[0] + bounds[1])), tenth(0.5 * (rows[0].y0 + rows[0].y1)),
                              0.0};
  const geometry::Point goal(tenth(0.5 * (bounds[rooms - 1] + bounds[rooms])),
                             tenth(0.5 * (rows[1].y0 + rows[1].y1)));
  builder.setStart(start);
  builder.addGoal(goal);

  // Boxes that close doors: the fire door's is heavy for odd seeds and light for even ones, so any two
  // consecutive seeds hold both cases (a coin can leave a run of seeds all heavy, and then none of those
  // offices has a corridor worth pushing through); room doors' alternate. The coin is still drawn so every
  // seed's other boxes stay where they were.
  static_cast<void>(random.chance(0.5));
  builder.addObject(geometry::Point(fire_x, corridor_mid), 0.5, kFireDoor - 0.1, 0.0,
                    seed % 2 == 1 ? ObjectWeight::Heavy : ObjectWeight::Light, random);
  for (std::size_t index = 0; index < blocked_doors.size(); ++index) {
    builder.addObject(blocked_doors[index].first, 0.5, kDoor - 0.1, 0.0,
                      index % 2 == 0 ? ObjectWeight::Heavy : ObjectWeight::Light, random);
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
