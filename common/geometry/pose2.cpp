#include "common/geometry/pose2.hpp"

#include "common/geometry/angle.hpp"

namespace ifar::geometry {

double wrapAngle(double radians)
{
  // remainder() lands in [-pi, pi]; the half-open range wants +pi for the boundary.
  const double wrapped = std::remainder(radians, 2.0 * kPi);
  return wrapped <= -kPi ? wrapped + 2.0 * kPi : wrapped;
}

Point Pose2::transform(const Point& body) const
{
  const double cosine = std::cos(heading);
  const double sine = std::sin(heading);
  return Point(x + cosine * body.x() - sine * body.y(), y + sine * body.x() + cosine * body.y());
}

Point Pose2::inverseTransform(const Point& parent) const
{
  const double cosine = std::cos(heading);
  const double sine = std::sin(heading);
  const double dx = parent.x() - x;
  const double dy = parent.y() - y;
  return Point(cosine * dx + sine * dy, -sine * dx + cosine * dy);
}

Pose2 Pose2::compose(const Pose2& other) const
{
  const Point position_in_parent = transform(other.position());
  return Pose2{position_in_parent.x(), position_in_parent.y(), wrapAngle(heading + other.heading)};
}

Pose2 Pose2::inverse() const
{
  const Point origin_in_body = inverseTransform(Point(0.0, 0.0));
  return Pose2{origin_in_body.x(), origin_in_body.y(), wrapAngle(-heading)};
}

}  // namespace ifar::geometry
