#include "sim/generators/world_builder.hpp"

#include <cmath>

#include "sim/world/world_geometry.hpp"

namespace ifar::sim {

WorldBuilder::WorldBuilder(std::string name, std::string source)
{
  world_.name = std::move(name);
  world_.source = std::move(source);
}

Box2 WorldBuilder::addRectangle(const std::string& prefix, const Box2& box, double height_m)
{
  StaticObstacle obstacle;
  obstacle.name = prefix + "_" + std::to_string(next_obstacle_++);
  obstacle.outline = {geometry::Point(box.x0, box.y0), geometry::Point(box.x1, box.y0),
                      geometry::Point(box.x1, box.y1), geometry::Point(box.x0, box.y1)};
  obstacle.height_m = height_m;
  world_.obstacles.push_back(std::move(obstacle));
  occupied_.push_back(box);
  return box;
}

void WorldBuilder::addObject(const geometry::Point& centre, double size_x, double size_y, double heading,
                             ObjectWeight weight, SeededRandom& random)
{
  MovableObject object;
  object.id = static_cast<std::int64_t>(world_.objects.size()) + 1;
  const bool light = weight == ObjectWeight::Light;
  object.name = std::string(light ? "light_box_" : "heavy_box_") + std::to_string(object.id);
  const double half_x = 0.5 * size_x;
  const double half_y = 0.5 * size_y;
  object.outline = {geometry::Point(-half_x, -half_y), geometry::Point(half_x, -half_y),
                    geometry::Point(half_x, half_y), geometry::Point(-half_x, half_y)};
  object.pose = {centre.x(), centre.y(), heading};
  // Round to 0.1 kg and 0.01 so world files read cleanly.
  object.mass_kg =
      std::round((light ? random.uniform(15.0, 40.0) : random.uniform(250.0, 400.0)) * 10.0) / 10.0;
  object.ground_friction =
      std::round((light ? random.uniform(0.4, 0.6) : random.uniform(0.6, 0.8)) * 100.0) / 100.0;
  object.height_m = light ? 0.8 : 1.2;
  world_.objects.push_back(object);
  const double reach = std::hypot(half_x, half_y);
  occupied_.push_back(Box2{centre.x() - reach, centre.y() - reach, centre.x() + reach, centre.y() + reach});
}

void WorldBuilder::addGoal(const geometry::Point& position)
{
  world_.goals.push_back(Goal{"goal_" + std::to_string(world_.goals.size()), position});
}

World WorldBuilder::build() const
{
  World world = world_;
  updateBounds(world);
  return world;
}

}  // namespace ifar::sim
