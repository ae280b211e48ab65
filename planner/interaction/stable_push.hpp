#pragma once
// Quasi-static stable pushing with a flat bumper (Lynch and Mason 1996, "Stable pushing: mechanics,
// controllability, and planning"): the object sticks to the bumper for every rotation centre in the
// set STABLE, built here from the friction cones at the two ends of the line contact and the object's
// ellipsoidal limit surface. The vehicle's rotation centre lies on its wheel axle line, so STABLE maps
// to turning radii: straight pushes and arcs with |radius| >= rho_min, per contact edge.
//
// Frames: "body" is the object's frame (centroid at the origin). The "contact frame" of a contact
// patch has its origin at the patch middle, x along the push direction (into the object) and y to
// the left of it.

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/plan_status.hpp"

namespace ifar::interaction {

/// Ellipsoidal approximation of the object's limit surface for uniform pressure over the footprint:
/// (|f| / max_force)^2 + (moment / max_moment)^2 = 1.
struct LimitSurface {
  double max_force_n = 0.0;              ///< ground friction x weight: the force of a pure translation
  double max_moment_nm = 0.0;            ///< the moment of a pure rotation about the centre of friction
  double characteristic_length_m = 0.0;  ///< c = max_moment / max_force (mean footprint radius)

  /// Force magnitude that moves the object about a rotation centre `distance_m` from its centre of
  /// friction (infinity = translation): max_force * R / sqrt(R^2 + c^2).
  double pushForce(double distance_m) const;
};

/// Valid when friction and mass are positive and finite; InvalidPhysics otherwise.
PlanStatus checkPhysics(const ObjectPhysics& physics, const PusherSettings& pusher);

/// Limit surface of a body-frame footprint (centroid at the origin). Needs checkPhysics() == Found.
LimitSurface ellipsoidalLimitSurface(const geometry::Polygon& footprint, const ObjectPhysics& physics);

/// Where the bumper touches one edge: centred on the centroid's projection, clamped to the edge.
struct ContactPatch {
  std::size_t edge = 0;
  geometry::Point start;  ///< body frame, first end along the counter-clockwise edge
  geometry::Point end;
  geometry::Point middle;           ///< where the bumper centre sits
  geometry::Vector push_direction;  ///< unit inward normal of the edge, body frame

  geometry::Point toContactFrame(const geometry::Point& body) const;
};
ContactPatch contactPatch(const geometry::Polygon& footprint, std::size_t edge, double bumper_width_m);

/// A closed half-plane {p : normal . (p - point) >= 0}.
struct HalfPlane {
  geometry::Point point;
  geometry::Vector normal;
  bool contains(const geometry::Point& candidate) const { return normal.dot(candidate - point) >= 0.0; }
};

/// The STABLE set of rotation centres for one contact patch, in its contact frame.
class StableRegion {
 public:
  StableRegion(const geometry::Polygon& footprint, const ContactPatch& patch, double bumper_friction,
               const LimitSurface& limit_surface);

  /// True when a rotation about `centre` (contact frame) keeps the object stuck to the bumper.
  bool contains(const geometry::Point& centre) const;

  /// Interval of y for which (x, y) is stable, restricted to y >= 0 (left) or y <= 0 (right);
  /// empty when low > high. Infinite ends mean unbounded.
  struct Interval {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    bool empty() const { return low > high; }
  };
  Interval stableAlongLine(double x, bool left) const;

 private:
  std::array<HalfPlane, 4> left_;   ///< for rotation centres with y >= 0 (the object turns left)
  std::array<HalfPlane, 4> right_;  ///< for y < 0
};

/// What the vehicle may do at one contact edge.
struct EdgePushOptions {
  ContactPatch patch;
  bool straight = false;  ///< straight pushes are stable
  /// Smallest stable turning radius of the vehicle's reference point for left (counter-clockwise) and
  /// right arcs; every larger radius is stable too. Infinity when no such arc family exists.
  double left_radius_m = std::numeric_limits<double>::infinity();
  double right_radius_m = std::numeric_limits<double>::infinity();
  double straight_force_n = 0.0;
  double left_force_n = 0.0;
  double right_force_n = 0.0;

  bool pushable() const { return straight || std::isfinite(left_radius_m) || std::isfinite(right_radius_m); }
};

/// Stable push options for every edge of the footprint (index = edge index).
std::vector<EdgePushOptions> edgePushOptions(const geometry::Polygon& footprint, const PusherSettings& pusher,
                                             const LimitSurface& limit_surface);

}  // namespace ifar::interaction
