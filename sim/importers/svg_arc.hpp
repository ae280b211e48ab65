#pragma once
// SVG elliptical arcs: from the endpoint form a path writes (radii, rotation, flags, end point) to the
// centre form a flattener samples (SVG 1.1 implementation notes F.6.5 and F.6.6).

#include "common/geometry/point.hpp"

namespace ifar::sim {

/// The centre parameterisation of an SVG arc from `start` to `end` (SVG implementation notes F.6.5, with
/// the radii scaled up as F.6.6 says when no ellipse of the given radii reaches both ends). Angles in
/// radians in the ellipse's own frame; `sweep_angle` is negative for a sweep against increasing angles.
struct SvgArcCentre {
  geometry::Point centre;
  double radius_x = 0.0;
  double radius_y = 0.0;
  double rotation = 0.0;  // of the ellipse's x axis, radians
  double start_angle = 0.0;
  double sweep_angle = 0.0;
  /// The point at parameter angle `angle`.
  geometry::Point pointAt(double angle) const;
};

/// Precondition: start != end and both radii non-zero (the grammar turns those cases into nothing and a
/// line). Radii are taken as absolute values.
SvgArcCentre svgArcCentre(const geometry::Point& start, double radius_x, double radius_y, double rotation_deg,
                          bool large_arc, bool sweep, const geometry::Point& end);

}  // namespace ifar::sim
