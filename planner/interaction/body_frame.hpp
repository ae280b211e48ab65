#pragma once
// Body-frame geometry of a pushed object carried to a world pose: polygons, directions, and the pose
// itself turned about a centre. Inline: the push search calls these for every pose it checks.

#include <cmath>

#include "common/geometry/angle.hpp"
#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"

namespace ifar::interaction {

/// Carries body-frame points to the world at one pose, as Pose2::transform does (the same arithmetic, so
/// the same bits), with the pose's cosine and sine taken once for all of them: a collision test carries
/// dozens of outline samples to every pose the push search checks.
class BodyToWorld {
 public:
  explicit BodyToWorld(const geometry::Pose2& pose)
      : x_(pose.x), y_(pose.y), cosine_(std::cos(pose.heading)), sine_(std::sin(pose.heading))
  {
  }

  geometry::Point operator()(const geometry::Point& body) const
  {
    return geometry::Point(x_ + cosine_ * body.x() - sine_ * body.y(),
                           y_ + sine_ * body.x() + cosine_ * body.y());
  }

 private:
  double x_;
  double y_;
  double cosine_;
  double sine_;
};

/// `body` (body frame) as it lies in the world at `pose`.
inline geometry::Polygon transformed(const geometry::Polygon& body, const geometry::Pose2& pose)
{
  const BodyToWorld to_world(pose);
  geometry::Polygon world;
  world.reserve(body.size());
  for (const geometry::Point& vertex : body) {
    world.push_back(to_world(vertex));
  }
  return world;
}

/// `vector` turned counter-clockwise by `angle` (radians).
inline geometry::Vector rotate(const geometry::Vector& vector, double angle)
{
  return geometry::Vector(std::cos(angle) * vector.x() - std::sin(angle) * vector.y(),
                          std::sin(angle) * vector.x() + std::cos(angle) * vector.y());
}

/// `pose` turned counter-clockwise by `angle` (radians) about the world point `centre`.
inline geometry::Pose2 rotateAbout(const geometry::Pose2& pose, const geometry::Point& centre, double angle)
{
  const double cosine = std::cos(angle);
  const double sine = std::sin(angle);
  const geometry::Vector offset = pose.position() - centre;
  return geometry::Pose2{centre.x() + cosine * offset.x() - sine * offset.y(),
                         centre.y() + sine * offset.x() + cosine * offset.y(),
                         geometry::wrapAngle(pose.heading + angle)};
}

}  // namespace ifar::interaction
