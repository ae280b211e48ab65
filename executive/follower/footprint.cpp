#include "executive/follower/footprint.hpp"

#include <cmath>

namespace ifar::executive {

double Footprint::circumradius() const
{
  return std::hypot((front_m + rear_m) / 2.0, half_width_m);
}

double Footprint::distanceFromBody(const geometry::Point& body_point) const
{
  const auto [outside_x, outside_y] = outsideRectangle(body_point);
  return std::hypot(outside_x, outside_y);
}

double Footprint::distance(const geometry::Pose2& pose, const geometry::Point& world_point) const
{
  // Written out instead of Pose2::inverseTransform so the hot loop stays inline.
  const double cosine = std::cos(pose.heading);
  const double sine = std::sin(pose.heading);
  const double dx = world_point.x() - pose.x;
  const double dy = world_point.y() - pose.y;
  return distanceFromBody({cosine * dx + sine * dy, -sine * dx + cosine * dy});
}

}  // namespace ifar::executive
