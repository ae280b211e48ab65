#pragma once
// Operations on convex polygons the push model needs and geometry does not offer: clipping by a
// half-plane or a convex window, and offsetting (growing or shrinking) by a distance.

#include <optional>

#include "common/geometry/polygon.hpp"

namespace ifar::interaction {

/// Keeps the part of the convex, counter-clockwise `polygon` where normal . (p - point) >= 0.
geometry::Polygon clipByHalfPlane(const geometry::Polygon& polygon, const geometry::Point& point,
                                  const geometry::Vector& normal);

/// Intersection of two convex counter-clockwise polygons (empty when they do not overlap).
geometry::Polygon clipConvex(const geometry::Polygon& subject, const geometry::Polygon& window);

/// Shrinks a convex counter-clockwise polygon by moving every edge inwards by `distance`; empty when
/// it vanishes.
geometry::Polygon erodeConvex(const geometry::Polygon& polygon, double distance);

/// Grows a convex counter-clockwise polygon by moving every edge outwards by `distance` (mitred
/// corners). Result vertex i lies between offset edges i - 1 and i.
geometry::Polygon dilateConvex(const geometry::Polygon& polygon, double distance);

/// Axis-aligned bounds.
struct Bounds {
  geometry::Point minimum;
  geometry::Point maximum;
  bool contains(const geometry::Point& point) const
  {
    return point.x() >= minimum.x() && point.x() <= maximum.x() && point.y() >= minimum.y() &&
           point.y() <= maximum.y();
  }
  bool overlaps(const Bounds& other) const
  {
    return minimum.x() <= other.maximum.x() && other.minimum.x() <= maximum.x() &&
           minimum.y() <= other.maximum.y() && other.minimum.y() <= maximum.y();
  }
};
Bounds boundsOf(const geometry::Polygon& polygon);

/// Distance from a segment to a polygon's closed region (0 when they touch or overlap).
double segmentPolygonDistance(const geometry::Segment& segment, const geometry::Polygon& polygon);

}  // namespace ifar::interaction
