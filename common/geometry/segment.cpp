#include "common/geometry/segment.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::geometry {
namespace {

/// -1, 0 or +1: the side of the line through `segment` on which `point` lies. Points within kEpsilon
/// of the line count as on it, so the decision does not flip on rounding noise.
int side(const Segment& segment, const Point& point)
{
  const double length = segment.length();
  if (length <= kEpsilon) {
    return 0;
  }
  const double signed_distance = cross(segment.start, segment.end, point) / length;
  if (signed_distance > kEpsilon) {
    return 1;
  }
  if (signed_distance < -kEpsilon) {
    return -1;
  }
  return 0;
}

bool onSegment(const Point& point, const Segment& segment)
{
  return distanceToSegment(point, segment) <= kEpsilon;
}

bool anyEndPointTouches(const Segment& first, const Segment& second)
{
  return onSegment(first.start, second) || onSegment(first.end, second) || onSegment(second.start, first) ||
         onSegment(second.end, first);
}

}  // namespace

Point closestPointOnSegment(const Point& point, const Segment& segment)
{
  const Vector direction = segment.end - segment.start;
  const double squared_length = direction.squaredNorm();
  if (squared_length <= kEpsilon * kEpsilon) {
    return segment.start;
  }
  const double parameter = std::clamp((point - segment.start).dot(direction) / squared_length, 0.0, 1.0);
  return segment.start + parameter * direction;
}

double distanceToSegment(const Point& point, const Segment& segment)
{
  return (point - closestPointOnSegment(point, segment)).norm();
}

bool segmentsCrossProperly(const Segment& first, const Segment& second)
{
  const int first_start_side = side(second, first.start);
  const int first_end_side = side(second, first.end);
  const int second_start_side = side(first, second.start);
  const int second_end_side = side(first, second.end);
  return first_start_side * first_end_side < 0 && second_start_side * second_end_side < 0 &&
         !anyEndPointTouches(first, second);
}

bool segmentsIntersect(const Segment& first, const Segment& second)
{
  // Either a crossing with both segments straddling each other, or an end point lies on the other
  // segment (covers touching, T-junctions, collinear overlap and zero-length segments).
  const int first_start_side = side(second, first.start);
  const int first_end_side = side(second, first.end);
  const int second_start_side = side(first, second.start);
  const int second_end_side = side(first, second.end);
  if (first_start_side * first_end_side < 0 && second_start_side * second_end_side < 0) {
    return true;
  }
  return anyEndPointTouches(first, second);
}

std::optional<Point> segmentIntersectionPoint(const Segment& first, const Segment& second)
{
  if (!segmentsIntersect(first, second)) {
    return std::nullopt;
  }
  const bool first_is_point = first.length() <= kEpsilon;
  const bool second_is_point = second.length() <= kEpsilon;
  if (first_is_point) {
    return first.start;
  }
  if (second_is_point) {
    return second.start;
  }
  const Vector first_direction = first.end - first.start;
  const Vector second_direction = second.end - second.start;
  const double denominator = cross(first_direction, second_direction);
  const bool parallel = std::abs(denominator) <= 1e-12 * first_direction.norm() * second_direction.norm();
  if (!parallel) {
    const double parameter =
        std::clamp(cross(second.start - first.start, second_direction) / denominator, 0.0, 1.0);
    return Point(first.start + parameter * first_direction);
  }
  // Collinear and touching: a single shared point only when the overlap has (near) zero length.
  const double first_length = first_direction.norm();
  const Vector unit = first_direction / first_length;
  const double second_start = (second.start - first.start).dot(unit);
  const double second_end = (second.end - first.start).dot(unit);
  const double overlap_begin = std::max(0.0, std::min(second_start, second_end));
  const double overlap_end = std::min(first_length, std::max(second_start, second_end));
  if (overlap_end - overlap_begin > kEpsilon) {
    return std::nullopt;
  }
  return Point(first.start + 0.5 * (overlap_begin + overlap_end) * unit);
}

}  // namespace ifar::geometry
