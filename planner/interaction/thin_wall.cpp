#include "planner/interaction/thin_wall.hpp"

#include <cmath>

namespace ifar::interaction {

using geometry::Vector;

std::optional<ThinWall> thinWall(const geometry::Polygon& obstacle, double inflation, double allowed_depth)
{
  if (obstacle.size() != 4) {
    return std::nullopt;
  }
  const Vector first = obstacle[1] - obstacle[0];
  const Vector second = obstacle[2] - obstacle[1];
  const bool rectangle = std::abs(first.dot(second)) <= 1e-9 * first.norm() * second.norm() &&
                         (obstacle[3] - obstacle[2] + first).norm() <= 1e-9 * first.norm();
  if (!rectangle) {
    return std::nullopt;
  }
  const bool first_shorter = first.norm() <= second.norm();
  const Vector& short_side = first_shorter ? first : second;
  const Vector& long_side = first_shorter ? second : first;
  const double half_width = short_side.norm() / 2.0;
  // The face ends where the inflation round its last cell begins.
  const double reach = long_side.norm() / 2.0 - inflation;
  if (half_width < inflation || half_width > allowed_depth || reach <= 0.0) {
    return std::nullopt;
  }
  ThinWall wall;
  wall.bounds = boundsOf(obstacle);
  wall.centre = (obstacle[0] + obstacle[2]) / 2.0;
  wall.across = short_side.normalized();
  wall.along = long_side.normalized();
  wall.reach = reach;
  return wall;
}

}  // namespace ifar::interaction
