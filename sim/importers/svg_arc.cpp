#include "sim/importers/svg_arc.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::sim {

geometry::Point SvgArcCentre::pointAt(double angle) const
{
  const double cos_rotation = std::cos(rotation);
  const double sin_rotation = std::sin(rotation);
  const double along_x = radius_x * std::cos(angle);
  const double along_y = radius_y * std::sin(angle);
  return centre + geometry::Point(cos_rotation * along_x - sin_rotation * along_y,
                                  sin_rotation * along_x + cos_rotation * along_y);
}

SvgArcCentre svgArcCentre(const geometry::Point& start, double radius_x, double radius_y, double rotation_deg,
                          bool large_arc, bool sweep, const geometry::Point& end)
{
  constexpr double kPi = 3.14159265358979323846;
  SvgArcCentre arc;
  arc.rotation = std::fmod(rotation_deg, 360.0) * kPi / 180.0;
  const double cos_rotation = std::cos(arc.rotation);
  const double sin_rotation = std::sin(arc.rotation);
  // F.6.5.1: the half chord in the ellipse's frame.
  const geometry::Point half = 0.5 * (start - end);
  const double x1 = cos_rotation * half.x() + sin_rotation * half.y();
  const double y1 = -sin_rotation * half.x() + cos_rotation * half.y();
  double rx = std::abs(radius_x);
  double ry = std::abs(radius_y);
  // F.6.6.2: radii too small for the chord grow, keeping their ratio, until the ellipse just reaches.
  const double reach = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
  if (reach > 1.0) {
    rx *= std::sqrt(reach);
    ry *= std::sqrt(reach);
  }
  // F.6.5.2: the centre in the ellipse's frame; rounding can make the radicand slightly negative.
  const double rx2 = rx * rx;
  const double ry2 = ry * ry;
  const double denominator = rx2 * y1 * y1 + ry2 * x1 * x1;
  const double radicand = denominator > 0.0 ? (rx2 * ry2 - denominator) / denominator : 0.0;
  double factor = std::sqrt(std::max(0.0, radicand));
  if (large_arc == sweep) {
    factor = -factor;
  }
  const double centre_x = factor * rx * y1 / ry;
  const double centre_y = -factor * ry * x1 / rx;
  // F.6.5.3: back to user space.
  arc.centre = geometry::Point(cos_rotation * centre_x - sin_rotation * centre_y,
                               sin_rotation * centre_x + cos_rotation * centre_y) +
               0.5 * (start + end);
  // F.6.5.5-6: start angle and sweep between the unit vectors to the two ends.
  const geometry::Point from((x1 - centre_x) / rx, (y1 - centre_y) / ry);
  const geometry::Point to((-x1 - centre_x) / rx, (-y1 - centre_y) / ry);
  arc.start_angle = std::atan2(from.y(), from.x());
  double sweep_angle = std::atan2(geometry::cross(from, to), from.dot(to));
  if (!sweep && sweep_angle > 0.0) {
    sweep_angle -= 2.0 * kPi;
  } else if (sweep && sweep_angle < 0.0) {
    sweep_angle += 2.0 * kPi;
  }
  arc.sweep_angle = sweep_angle;
  arc.radius_x = rx;
  arc.radius_y = ry;
  return arc;
}

}  // namespace ifar::sim
