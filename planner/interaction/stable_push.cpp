#include "planner/interaction/stable_push.hpp"

#include <algorithm>
#include <cmath>

#include "common/vehicle_model.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Vector;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Arcs tighter than this are never offered: the vehicle would pivot on the object.
constexpr double kSmallestRadius = 0.1;
/// Sub-triangles per triangle side when integrating the footprint's mean radius.
constexpr int kQuadratureDivisions = 8;

bool positiveFinite(double value)
{
  return std::isfinite(value) && value > 0.0;
}

/// Mean distance of the (uniformly loaded) footprint's points from the origin.
double meanRadius(const Polygon& footprint)
{
  double weighted = 0.0;
  double total_area = 0.0;
  const std::size_t count = footprint.size();
  const double cells = kQuadratureDivisions * kQuadratureDivisions;
  for (std::size_t index = 0; index < count; ++index) {
    const Point& b = footprint[index];
    const Point& c = footprint[(index + 1) % count];
    const double triangle_area = std::abs(geometry::cross(b, c)) / 2.0;
    const auto lattice = [&](double u, double v) {
      return Point(b * (u / kQuadratureDivisions) + c * (v / kQuadratureDivisions));
    };
    double sum = 0.0;
    for (int i = 0; i < kQuadratureDivisions; ++i) {
      for (int j = 0; j + i < kQuadratureDivisions; ++j) {
        sum += lattice(i + 1.0 / 3.0, j + 1.0 / 3.0).norm();
        if (i + j + 1 < kQuadratureDivisions) {
          sum += lattice(i + 2.0 / 3.0, j + 2.0 / 3.0).norm();
        }
      }
    }
    weighted += sum * triangle_area / cells;
    total_area += triangle_area;
  }
  return total_area > 0.0 ? weighted / total_area : 0.0;
}

/// The footprint vertex farthest from `from` along `direction`.
Point farthestAlong(const Polygon& contact_footprint, const Point& from, const Vector& direction)
{
  Point best = from;
  double best_reach = 0.0;
  for (const Point& vertex : contact_footprint) {
    const double reach = direction.dot(vertex - from);
    if (reach > best_reach) {
      best_reach = reach;
      best = vertex;
    }
  }
  return best;
}

/// Narrows `interval` to the y with normal . ((x, y) - point) >= 0.
void narrow(StableRegion::Interval& interval, const HalfPlane& plane, double x)
{
  const double constant = plane.normal.x() * (x - plane.point.x()) - plane.normal.y() * plane.point.y();
  // Condition: normal.y * y + constant >= 0.
  if (std::abs(plane.normal.y()) <= 1e-12) {
    if (constant < 0.0) {
      interval.low = kInfinity;
      interval.high = -kInfinity;
    }
    return;
  }
  const double bound = -constant / plane.normal.y();
  if (plane.normal.y() > 0.0) {
    interval.low = std::max(interval.low, bound);
  } else {
    interval.high = std::min(interval.high, bound);
  }
}

}  // namespace

double LimitSurface::pushForce(double distance_m) const
{
  if (!std::isfinite(distance_m)) {
    return max_force_n;
  }
  return max_force_n * distance_m / std::hypot(distance_m, characteristic_length_m);
}

PlanStatus checkPhysics(const ObjectPhysics& physics, const PusherSettings& pusher)
{
  if (!positiveFinite(physics.ground_friction) || !positiveFinite(physics.mass_kg) ||
      !std::isfinite(pusher.bumper_friction) || pusher.bumper_friction < 0.0 ||
      !positiveFinite(pusher.bumper_width_m) || !std::isfinite(pusher.bumper_to_axle_m) ||
      pusher.bumper_to_axle_m < 0.0 || !positiveFinite(pusher.max_push_force_n)) {
    return PlanStatus::InvalidPhysics;
  }
  return PlanStatus::Found;
}

LimitSurface ellipsoidalLimitSurface(const Polygon& footprint, const ObjectPhysics& physics)
{
  LimitSurface surface;
  surface.max_force_n = physics.ground_friction * physics.mass_kg * common::kGravity;
  surface.characteristic_length_m = meanRadius(footprint);
  surface.max_moment_nm = surface.max_force_n * surface.characteristic_length_m;
  return surface;
}

Point ContactPatch::toContactFrame(const Point& body) const
{
  const Vector offset = body - middle;
  return Point(offset.dot(push_direction), geometry::cross(push_direction, offset));
}

ContactPatch contactPatch(const Polygon& footprint, std::size_t edge, double bumper_width_m)
{
  const std::size_t count = footprint.size();
  const Point& first = footprint[edge % count];
  const Point& second = footprint[(edge + 1) % count];
  const double length = (second - first).norm();
  const Vector along = (second - first) / length;
  ContactPatch patch;
  patch.edge = edge % count;
  patch.push_direction = Vector(-along.y(), along.x());  // inward for counter-clockwise footprints
  if (length <= bumper_width_m) {
    patch.start = first;
    patch.end = second;
  } else {
    const double half = bumper_width_m / 2.0;
    const double centre = std::clamp(along.dot(Point::Zero() - first), half, length - half);
    patch.start = first + along * (centre - half);
    patch.end = first + along * (centre + half);
  }
  patch.middle = (patch.start + patch.end) / 2.0;
  return patch;
}

StableRegion::StableRegion(const Polygon& footprint, const ContactPatch& patch, double bumper_friction,
                           const LimitSurface& limit_surface)
{
  Polygon contact_footprint;
  contact_footprint.reserve(footprint.size());
  for (const Point& vertex : footprint) {
    contact_footprint.push_back(patch.toContactFrame(vertex));
  }
  const Point centre = patch.toContactFrame(Point::Zero());
  Point left_end = patch.toContactFrame(patch.start);
  Point right_end = patch.toContactFrame(patch.end);
  if (left_end.y() < right_end.y()) {
    std::swap(left_end, right_end);
  }
  const double half_angle = std::atan(bumper_friction);
  const double cosine = std::cos(half_angle);
  const double sine = std::sin(half_angle);

  // Friction cones at the contact ends: centres beyond the lines perpendicular to the outer cone edges.
  const Vector up_edge(cosine, sine);
  const Vector down_edge(cosine, -sine);
  left_[0] = HalfPlane{left_end, Vector(-cosine, sine)};
  left_[1] = HalfPlane{farthestAlong(contact_footprint, right_end, up_edge), up_edge};
  right_[0] = HalfPlane{right_end, Vector(-cosine, -sine)};
  right_[1] = HalfPlane{farthestAlong(contact_footprint, left_end, down_edge), down_edge};

  // Contact wrench: the contact force stays inside the bumper segment. Bisector lines between each end
  // and the centre of friction, and the limit-surface image (c^2 / p) of forces through the ends.
  const double c_squared = limit_surface.characteristic_length_m * limit_surface.characteristic_length_m;
  const Vector from_left = centre - left_end;
  const Vector from_right = centre - right_end;
  left_[2] = HalfPlane{(left_end + centre) / 2.0, left_end - centre};
  left_[3] = HalfPlane{centre + from_right * (c_squared / from_right.squaredNorm()), from_right};
  right_[2] = HalfPlane{(right_end + centre) / 2.0, right_end - centre};
  right_[3] = HalfPlane{centre + from_left * (c_squared / from_left.squaredNorm()), from_left};
}

bool StableRegion::contains(const Point& centre) const
{
  const auto& planes = centre.y() >= 0.0 ? left_ : right_;
  return std::all_of(planes.begin(), planes.end(),
                     [&](const HalfPlane& plane) { return plane.contains(centre); });
}

StableRegion::Interval StableRegion::stableAlongLine(double x, bool left) const
{
  Interval interval;
  if (left) {
    interval.low = 0.0;
  } else {
    interval.high = 0.0;
  }
  for (const HalfPlane& plane : left ? left_ : right_) {
    narrow(interval, plane, x);
  }
  return interval;
}

std::vector<EdgePushOptions> edgePushOptions(const Polygon& footprint, const PusherSettings& pusher,
                                             const LimitSurface& limit_surface)
{
  std::vector<EdgePushOptions> options;
  options.reserve(footprint.size());
  const double axle_x = -pusher.bumper_to_axle_m;
  for (std::size_t edge = 0; edge < footprint.size(); ++edge) {
    EdgePushOptions option;
    option.patch = contactPatch(footprint, edge, pusher.bumper_width_m);
    const StableRegion region(footprint, option.patch, pusher.bumper_friction, limit_surface);
    const StableRegion::Interval left = region.stableAlongLine(axle_x, true);
    const StableRegion::Interval right = region.stableAlongLine(axle_x, false);
    const bool left_unbounded = !left.empty() && !std::isfinite(left.high);
    const bool right_unbounded = !right.empty() && !std::isfinite(right.low);
    option.straight = left_unbounded && right_unbounded;
    const Point centre = option.patch.toContactFrame(Point::Zero());
    if (left_unbounded) {
      option.left_radius_m = std::max(left.low, kSmallestRadius);
      option.left_force_n = limit_surface.pushForce((Point(axle_x, option.left_radius_m) - centre).norm());
    }
    if (right_unbounded) {
      option.right_radius_m = std::max(-right.high, kSmallestRadius);
      option.right_force_n = limit_surface.pushForce((Point(axle_x, -option.right_radius_m) - centre).norm());
    }
    option.straight_force_n = limit_surface.max_force_n;
    options.push_back(option);
  }
  return options;
}

}  // namespace ifar::interaction
