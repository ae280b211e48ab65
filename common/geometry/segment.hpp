#pragma once
// Line segments and their intersection, with the degenerate cases spelled out: zero-length segments are
// points, collinear overlaps and touching end points count as intersections.

#include <optional>

#include "common/geometry/point.hpp"

namespace ifar::geometry {

struct Segment {
  Point start;
  Point end;
  double length() const { return (end - start).norm(); }
};

/// True when the closed segments share at least one point (touching and collinear overlap included).
bool segmentsIntersect(const Segment& first, const Segment& second);

/// True when the segments cross at a single point interior to both (no touching, no collinear overlap).
/// This is the test a visibility edge uses against obstacle edges.
bool segmentsCrossProperly(const Segment& first, const Segment& second);

/// The intersection point when the segments meet at exactly one point; empty when they do not meet or
/// overlap along a stretch (collinear).
std::optional<Point> segmentIntersectionPoint(const Segment& first, const Segment& second);

/// Euclidean distance from `point` to the closed segment (to the point when the segment has zero length).
double distanceToSegment(const Point& point, const Segment& segment);

/// The point of the segment closest to `point`.
Point closestPointOnSegment(const Point& point, const Segment& segment);

}  // namespace ifar::geometry
