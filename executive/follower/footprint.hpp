#pragma once
// The vehicle's outline in its body frame: a rectangle from the rear to the bumper face.

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"

namespace ifar::executive {

struct Footprint {
  double front_m = 0.45;  ///< reference point to the bumper face, metres (forward)
  double rear_m = 0.45;   ///< reference point to the rear, metres (backward)
  double half_width_m = 0.35;

  /// Centre of the rectangle in the body frame.
  geometry::Point bodyCentre() const { return {(front_m - rear_m) / 2.0, 0.0}; }
  /// Radius of the circle around bodyCentre() that holds the rectangle.
  double circumradius() const;
  /// Distance from a body-frame point to the rectangle; 0 inside or on it.
  double distanceFromBody(const geometry::Point& body_point) const;
  /// The square of distanceFromBody, without the square root: for picking the nearest of many points
  /// (inline: the follower calls it for every point near every sample of every arc).
  double squaredDistanceFromBody(const geometry::Point& body_point) const
  {
    const auto [outside_x, outside_y] = outsideRectangle(body_point);
    return outside_x * outside_x + outside_y * outside_y;
  }
  /// How far a body-frame point lies beyond the rectangle along each body axis (0 where it is within).
  std::pair<double, double> outsideRectangle(const geometry::Point& body_point) const
  {
    const double half_length = (front_m + rear_m) / 2.0;
    const double offset_x = body_point.x() - bodyCentre().x();
    return {std::max(std::abs(offset_x) - half_length, 0.0),
            std::max(std::abs(body_point.y()) - half_width_m, 0.0)};
  }
  /// Distance from a world point to the rectangle placed at `pose`.
  double distance(const geometry::Pose2& pose, const geometry::Point& world_point) const;
};

}  // namespace ifar::executive
