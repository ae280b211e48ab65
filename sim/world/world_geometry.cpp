#include "sim/world/world_geometry.hpp"

#include <algorithm>

namespace ifar::sim {

geometry::Polygon placedOutline(const MovableObject& object)
{
  return placedOutline(object, object.pose);
}

geometry::Polygon placedOutline(const MovableObject& object, const geometry::Pose2& pose)
{
  geometry::Polygon placed;
  placed.reserve(object.outline.size());
  for (const auto& vertex : object.outline) {
    placed.push_back(pose.transform(vertex));
  }
  return placed;
}

double slidingForce(const MovableObject& object)
{
  return object.ground_friction * object.mass_kg * common::kGravity;
}

bool isPushable(const MovableObject& object, const common::VehicleSettings& vehicle)
{
  return slidingForce(object) < vehicle.maxPushForce();
}

namespace {

void extend(geometry::Point& low, geometry::Point& high, const geometry::Point& point)
{
  low = low.cwiseMin(point);
  high = high.cwiseMax(point);
}

bool strictlyInside(const geometry::Polygon& polygon, const geometry::Point& point)
{
  return geometry::locatePoint(polygon, point) == geometry::Containment::Inside;
}

/// True when some sample of `first` (vertex, edge midpoint or centroid) lies strictly inside `second`.
bool sampleInside(const geometry::Polygon& first, const geometry::Polygon& second)
{
  const std::size_t count = first.size();
  for (std::size_t index = 0; index < count; ++index) {
    const auto& vertex = first[index];
    const auto& next = first[(index + 1) % count];
    if (strictlyInside(second, vertex) || strictlyInside(second, 0.5 * (vertex + next))) {
      return true;
    }
  }
  return count >= 3 && strictlyInside(first, geometry::centroid(first)) &&
         strictlyInside(second, geometry::centroid(first));
}

}  // namespace

void updateBounds(World& world)
{
  geometry::Point low = world.start.position();
  geometry::Point high = low;
  for (const auto& obstacle : world.obstacles) {
    for (const auto& vertex : obstacle.outline) {
      extend(low, high, vertex);
    }
  }
  for (const auto& object : world.objects) {
    for (const auto& vertex : placedOutline(object)) {
      extend(low, high, vertex);
    }
  }
  for (const auto& goal : world.goals) {
    extend(low, high, goal.position);
  }
  world.bounds_min = low;
  world.bounds_max = high;
}

bool interiorsOverlap(const geometry::Polygon& first, const geometry::Polygon& second)
{
  if (first.size() < 3 || second.size() < 3) {
    return false;
  }
  for (std::size_t i = 0; i < first.size(); ++i) {
    const auto edge = geometry::polygonEdge(first, i);
    for (std::size_t j = 0; j < second.size(); ++j) {
      if (geometry::segmentsCrossProperly(edge, geometry::polygonEdge(second, j))) {
        return true;
      }
    }
  }
  return sampleInside(first, second) || sampleInside(second, first);
}

}  // namespace ifar::sim
