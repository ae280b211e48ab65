#include "planner/interaction/convex_polygon.hpp"

#include <algorithm>
#include <limits>

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Vector;

Polygon clipByHalfPlane(const Polygon& polygon, const Point& point, const Vector& normal)
{
  Polygon result;
  const std::size_t count = polygon.size();
  for (std::size_t index = 0; index < count; ++index) {
    const Point& current = polygon[index];
    const Point& next = polygon[(index + 1) % count];
    const double current_side = normal.dot(current - point);
    const double next_side = normal.dot(next - point);
    if (current_side >= 0.0) {
      result.push_back(current);
    }
    if ((current_side >= 0.0) != (next_side >= 0.0)) {
      const double fraction = current_side / (current_side - next_side);
      result.push_back(current + fraction * (next - current));
    }
  }
  return result;
}

Polygon clipConvex(const Polygon& subject, const Polygon& window)
{
  Polygon result = subject;
  const std::size_t count = window.size();
  for (std::size_t index = 0; index < count && !result.empty(); ++index) {
    const Vector direction = window[(index + 1) % count] - window[index];
    result = clipByHalfPlane(result, window[index], Vector(-direction.y(), direction.x()));
  }
  return result;
}

Polygon erodeConvex(const Polygon& polygon, double distance)
{
  Polygon result = polygon;
  const std::size_t count = polygon.size();
  for (std::size_t index = 0; index < count && !result.empty(); ++index) {
    const Vector direction = polygon[(index + 1) % count] - polygon[index];
    const double length = direction.norm();
    if (length <= geometry::kEpsilon) {
      continue;
    }
    const Vector inward(-direction.y() / length, direction.x() / length);
    result = clipByHalfPlane(result, polygon[index] + inward * distance, inward);
  }
  if (result.size() < 3 || geometry::area(result) <= geometry::kEpsilon) {
    return {};
  }
  return result;
}

Polygon dilateConvex(const Polygon& polygon, double distance)
{
  const std::size_t count = polygon.size();
  Polygon result;
  result.reserve(count);
  for (std::size_t index = 0; index < count; ++index) {
    const Point& previous = polygon[(index + count - 1) % count];
    const Point& current = polygon[index];
    const Point& next = polygon[(index + 1) % count];
    const Vector incoming = (current - previous).normalized();
    const Vector outgoing = (next - current).normalized();
    // Outward normals of a counter-clockwise polygon point to the right of each edge.
    const Vector incoming_normal(incoming.y(), -incoming.x());
    const Vector outgoing_normal(outgoing.y(), -outgoing.x());
    const Vector bisector = incoming_normal + outgoing_normal;
    const double cosine = std::max(0.25, bisector.norm() / 2.0);  // caps the mitre at sharp corners
    result.push_back(current + bisector.normalized() * (distance / cosine));
  }
  return result;
}

Bounds boundsOf(const Polygon& polygon)
{
  Bounds bounds{Point(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()),
                Point(-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity())};
  for (const Point& vertex : polygon) {
    bounds.minimum = bounds.minimum.cwiseMin(vertex);
    bounds.maximum = bounds.maximum.cwiseMax(vertex);
  }
  return bounds;
}

double segmentPolygonDistance(const geometry::Segment& segment, const Polygon& polygon)
{
  if (geometry::containsPoint(polygon, segment.start) || geometry::containsPoint(polygon, segment.end)) {
    return 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  const std::size_t count = polygon.size();
  for (std::size_t index = 0; index < count; ++index) {
    const geometry::Segment edge = geometry::polygonEdge(polygon, index);
    if (geometry::segmentsIntersect(edge, segment)) {
      return 0.0;
    }
    best = std::min({best, geometry::distanceToSegment(edge.start, segment),
                     geometry::distanceToSegment(edge.end, segment),
                     geometry::distanceToSegment(segment.start, edge),
                     geometry::distanceToSegment(segment.end, edge)});
  }
  return best;
}

}  // namespace ifar::interaction
