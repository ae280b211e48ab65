#pragma once
// A rigid transform in the plane: position and heading (radians, counter-clockwise from +x).

#include <cmath>

#include "common/geometry/point.hpp"

namespace ifar::geometry {

/// Wraps an angle to (-pi, pi].
double wrapAngle(double radians);

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double heading = 0.0;

  Point position() const { return Point(x, y); }
  /// Maps a point from this pose's body frame into the parent frame.
  Point transform(const Point& body) const;
  /// Maps a point from the parent frame into this pose's body frame.
  Point inverseTransform(const Point& parent) const;
  /// this * other: `other` expressed in this pose's frame, returned in the parent frame.
  Pose2 compose(const Pose2& other) const;
  Pose2 inverse() const;
};

}  // namespace ifar::geometry
