#include <cmath>

#include "common/geometry/angle.hpp"
#include "sim/generators/generators.hpp"
#include "sim/generators/world_builder.hpp"

namespace ifar::sim {
namespace {

constexpr double kSize = 32.0;
constexpr double kWall = 0.3;
constexpr double kPartitionY = 16.0;
constexpr double kDoorWidth = 1.4;
constexpr double kOpeningWidth = 4.0;

struct RoomLayout {
  double door_x = 8.0;       // centre of the doorway in the partition (the short cut)
  double opening_x0 = 24.0;  // left end of the wide opening (the long way round)
  geometry::Pose2 start{8.0, 4.0, geometry::kPi / 2.0};  // straight below the doorway
  geometry::Point goal{8.0, 26.0};
};

Box2 doorZone(const RoomLayout& layout)
{
  return {layout.door_x - 2.0, kPartitionY - 2.5, layout.door_x + 2.0, kPartitionY + 2.5};
}

Box2 openingZone(const RoomLayout& layout)
{
  return {layout.opening_x0 - 1.0, kPartitionY - 2.5, layout.opening_x0 + kOpeningWidth + 1.0,
          kPartitionY + 2.5};
}

void addWalls(WorldBuilder& builder, const RoomLayout& layout)
{
  builder.addRectangle("wall", {0.0, 0.0, kSize, kWall});
  builder.addRectangle("wall", {0.0, kSize - kWall, kSize, kSize});
  builder.addRectangle("wall", {0.0, kWall, kWall, kSize - kWall});
  builder.addRectangle("wall", {kSize - kWall, kWall, kSize, kSize - kWall});
  const double y0 = kPartitionY - 0.5 * kWall;
  const double y1 = kPartitionY + 0.5 * kWall;
  builder.addRectangle("partition", {kWall, y0, layout.door_x - 0.5 * kDoorWidth, y1});
  builder.addRectangle("partition", {layout.door_x + 0.5 * kDoorWidth, y0, layout.opening_x0, y1});
  builder.addRectangle("partition", {layout.opening_x0 + kOpeningWidth, y0, kSize - kWall, y1});
}

/// True when `box` keeps `margin` from everything placed and clear of the passages, start and goal.
bool clear(const WorldBuilder& builder, const RoomLayout& layout, const Box2& box, double margin)
{
  for (const auto& other : builder.occupied()) {
    if (box.overlaps(other, margin)) {
      return false;
    }
  }
  return !box.overlaps(doorZone(layout)) && !box.overlaps(openingZone(layout)) &&
         !box.contains(layout.start.position(), 1.5) && !box.contains(layout.goal, 1.5);
}

void addFurniture(WorldBuilder& builder, const RoomLayout& layout, SeededRandom& random, int count)
{
  for (int placed = 0, tries = 0; placed < count && tries < 500; ++tries) {
    const double width = random.uniform(0.6, 2.5);
    const double depth = random.uniform(0.6, 2.5);
    const double x = random.uniform(1.5, kSize - 1.5 - width);
    const double y = random.uniform(1.5, kSize - 1.5 - depth);
    const Box2 box{std::round(x * 10) / 10, std::round(y * 10) / 10, std::round((x + width) * 10) / 10,
                   std::round((y + depth) * 10) / 10};
    if (clear(builder, layout, box, 1.2)) {
      builder.addRectangle("furniture", box, 0.9);
      ++placed;
    }
  }
}

void addScatteredBoxes(WorldBuilder& builder, const RoomLayout& layout, SeededRandom& random, int count)
{
  for (int placed = 0, tries = 0; placed < count && tries < 500; ++tries) {
    const double size_x = random.uniform(0.5, 1.2);
    const double size_y = random.uniform(0.5, 1.2);
    const geometry::Point centre(random.uniform(2.0, kSize - 2.0), random.uniform(2.0, kSize - 2.0));
    const double reach = std::hypot(size_x, size_y) / 2.0;
    const Box2 box{centre.x() - reach, centre.y() - reach, centre.x() + reach, centre.y() + reach};
    if (clear(builder, layout, box, 1.0)) {
      const double heading = random.uniform(-geometry::kPi, geometry::kPi);
      builder.addObject(centre, size_x, size_y, heading,
                        placed % 2 == 0 ? ObjectWeight::Light : ObjectWeight::Heavy, random);
      ++placed;
    }
  }
}

void addDoorwayBox(WorldBuilder& builder, const RoomLayout& layout, ObjectWeight weight, SeededRandom& random)
{
  // 1.3 m across a 1.4 m doorway: the 0.7 m vehicle cannot pass beside it.
  builder.addObject(geometry::Point(layout.door_x, kPartitionY), kDoorWidth - 0.1, 0.6, 0.0, weight, random);
}

}  // namespace

World generateRoom(std::uint64_t seed, bool with_objects)
{
  SeededRandom random(seed);
  RoomLayout layout;
  layout.door_x = std::round(random.uniform(5.0, 14.0) * 10) / 10;
  layout.opening_x0 = std::round(random.uniform(20.0, 26.0) * 10) / 10;
  layout.start = {std::round(random.uniform(2.0, 12.0) * 10) / 10,
                  std::round(random.uniform(2.0, 6.0) * 10) / 10, geometry::kPi / 2.0};
  layout.goal = {std::round(random.uniform(2.0, 14.0) * 10) / 10,
                 std::round(random.uniform(26.0, 30.0) * 10) / 10};

  const std::string name = with_objects ? "room_objects" : "room";
  WorldBuilder builder(name, "generator " + name + " seed " + std::to_string(seed));
  addWalls(builder, layout);
  addFurniture(builder, layout, random, 6);
  builder.setStart(layout.start);
  builder.addGoal(layout.goal);
  if (with_objects) {
    // Objects come after the static layout in the random stream, so Room and RoomObjects share walls.
    const ObjectWeight doorway = random.chance(0.5) ? ObjectWeight::Light : ObjectWeight::Heavy;
    addDoorwayBox(builder, layout, doorway, random);
    addScatteredBoxes(builder, layout, random, 8);
  }
  return builder.build();
}

World generateDemoRoom()
{
  SeededRandom random(1);  // only masses and frictions; the layout is fixed
  const RoomLayout layout;
  WorldBuilder builder("demo_room", "generator demo_room");
  addWalls(builder, layout);
  builder.addRectangle("furniture", {14.0, 6.0, 16.0, 7.0}, 0.9);
  builder.addRectangle("furniture", {3.0, 22.0, 4.5, 24.0}, 0.9);
  builder.addRectangle("furniture", {18.0, 24.0, 20.5, 25.0}, 0.9);
  builder.setStart(layout.start);
  builder.addGoal(layout.goal);
  addDoorwayBox(builder, layout, ObjectWeight::Light, random);
  builder.addObject(geometry::Point(12.0, 10.0), 1.0, 1.0, 0.3, ObjectWeight::Heavy, random);
  builder.addObject(geometry::Point(20.0, 20.0), 0.8, 0.6, 0.0, ObjectWeight::Light, random);
  builder.addObject(geometry::Point(27.0, 28.0), 1.2, 1.0, 0.0, ObjectWeight::Heavy, random);
  return builder.build();
}

}  // namespace ifar::sim
