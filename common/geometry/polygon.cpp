#include "common/geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/geometry/box_sweep.hpp"

namespace ifar::geometry {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

/// The polygon without consecutive duplicate vertices (including last == first).
Polygon withoutRepeatedVertices(const Polygon& polygon)
{
  Polygon result;
  result.reserve(polygon.size());
  for (const Point& vertex : polygon) {
    if (result.empty() || (vertex - result.back()).norm() > kEpsilon) {
      result.push_back(vertex);
    }
  }
  while (result.size() > 1 && (result.front() - result.back()).norm() <= kEpsilon) {
    result.pop_back();
  }
  return result;
}

}  // namespace

double signedArea(const Polygon& polygon)
{
  const std::size_t count = polygon.size();
  if (count < 3) {
    return 0.0;
  }
  double twice_area = 0.0;
  for (std::size_t index = 0; index < count; ++index) {
    twice_area += cross(polygon[index], polygon[(index + 1) % count]);
  }
  return 0.5 * twice_area;
}

double area(const Polygon& polygon)
{
  return std::abs(signedArea(polygon));
}

Eigen::AlignedBox2d boundingBox(const Polygon& polygon)
{
  Eigen::AlignedBox2d box;
  for (const Point& vertex : polygon) {
    box.extend(vertex);
  }
  return box;
}

Point centroid(const Polygon& polygon)
{
  if (polygon.empty()) {
    return Point(0.0, 0.0);
  }
  const double signed_area = signedArea(polygon);
  if (std::abs(signed_area) <= kEpsilon) {
    // Degenerate polygon: the vertex mean is the only sensible centre.
    Point sum(0.0, 0.0);
    for (const Point& vertex : polygon) {
      sum += vertex;
    }
    return sum / static_cast<double>(polygon.size());
  }
  // Relative to the first vertex to keep precision far from the origin.
  const Point& origin = polygon.front();
  Point weighted(0.0, 0.0);
  const std::size_t count = polygon.size();
  for (std::size_t index = 0; index < count; ++index) {
    const Vector current = polygon[index] - origin;
    const Vector next = polygon[(index + 1) % count] - origin;
    weighted += (current + next) * cross(current, next);
  }
  return origin + weighted / (6.0 * signed_area);
}

double perimeter(const Polygon& polygon)
{
  if (polygon.size() < 2) {
    return 0.0;
  }
  double total = 0.0;
  for (std::size_t index = 0; index < polygon.size(); ++index) {
    total += polygonEdge(polygon, index).length();
  }
  return total;
}

Segment polygonEdge(const Polygon& polygon, std::size_t index)
{
  return Segment{polygon[index], polygon[(index + 1) % polygon.size()]};
}

Polygon counterClockwise(Polygon polygon)
{
  if (signedArea(polygon) < 0.0) {
    std::reverse(polygon.begin(), polygon.end());
  }
  return polygon;
}

Containment locatePoint(const Polygon& polygon, const Point& point)
{
  const std::size_t count = polygon.size();
  if (count == 0) {
    return Containment::Outside;
  }
  for (std::size_t index = 0; index < count; ++index) {
    if (distanceToSegment(point, polygonEdge(polygon, index)) <= kEpsilon) {
      return Containment::Boundary;
    }
  }
  if (count < 3) {
    return Containment::Outside;
  }
  // Even-odd rule with a ray towards +x; half-open edge rule so a vertex on the ray counts once.
  bool inside = false;
  for (std::size_t index = 0, previous = count - 1; index < count; previous = index++) {
    const Point& a = polygon[index];
    const Point& b = polygon[previous];
    if ((a.y() > point.y()) != (b.y() > point.y())) {
      const double crossing_x = a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (point.x() < crossing_x) {
        inside = !inside;
      }
    }
  }
  return inside ? Containment::Inside : Containment::Outside;
}

bool containsPoint(const Polygon& polygon, const Point& point)
{
  return locatePoint(polygon, point) != Containment::Outside;
}

bool isConvex(const Polygon& polygon)
{
  const Polygon vertices = withoutRepeatedVertices(polygon);
  const std::size_t count = vertices.size();
  if (count < 3 || area(vertices) <= kEpsilon) {
    return false;
  }
  int turn_sign = 0;
  double total_turn = 0.0;
  for (std::size_t index = 0; index < count; ++index) {
    const Vector incoming = vertices[index] - vertices[(index + count - 1) % count];
    const Vector outgoing = vertices[(index + 1) % count] - vertices[index];
    const double turn = cross(incoming, outgoing);
    const double along = incoming.dot(outgoing);
    if (std::abs(turn) <= kEpsilon * incoming.norm() * outgoing.norm()) {
      if (along < 0.0) {
        return false;  // the boundary doubles back on itself
      }
      continue;  // collinear vertex
    }
    const int sign = turn > 0.0 ? 1 : -1;
    if (turn_sign != 0 && sign != turn_sign) {
      return false;
    }
    turn_sign = sign;
    total_turn += std::atan2(turn, along);
  }
  // All turns the same way but winding twice (a pentagram) is not convex.
  return std::abs(std::abs(total_turn) - kTwoPi) < 1e-6;
}

bool isSimple(const Polygon& polygon)
{
  const std::size_t count = polygon.size();
  if (count < 3) {
    return false;
  }
  std::vector<Eigen::AlignedBox2d> boxes;
  boxes.reserve(count);
  for (std::size_t index = 0; index < count; ++index) {
    const Segment edge = polygonEdge(polygon, index);
    if (!(edge.length() > kEpsilon)) {
      return false;
    }
    Eigen::AlignedBox2d box(edge.start);
    box.extend(edge.end);
    boxes.push_back(box);
  }
  // Only edges whose boxes come within the intersection tolerance can meet.
  for (const auto& [first, second] : overlappingBoxPairs(
           common::Span<const Eigen::AlignedBox2d>(boxes.data(), boxes.size()), 2.0 * kEpsilon)) {
    const Segment first_edge = polygonEdge(polygon, first);
    const Segment second_edge = polygonEdge(polygon, second);
    const bool adjacent = second == first + 1 || (first == 0 && second == count - 1);
    if (!adjacent) {
      if (segmentsIntersect(first_edge, second_edge)) {
        return false;
      }
      continue;
    }
    // Adjacent edges share one vertex; any other common point means they fold back.
    const Point shared = second == first + 1 ? first_edge.end : first_edge.start;
    const auto meeting = segmentIntersectionPoint(first_edge, second_edge);
    if (!meeting || (*meeting - shared).norm() > kEpsilon) {
      return false;
    }
  }
  return true;
}

Polygon convexHull(std::vector<Point> points)
{
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end(),
                           [](const Point& a, const Point& b) { return (a - b).norm() <= kEpsilon; }),
               points.end());
  if (points.size() < 3) {
    return points;
  }
  Polygon hull(2 * points.size());
  std::size_t size = 0;
  // Lower chain, then upper chain; a non-left turn (including collinear) pops the middle point.
  for (const Point& point : points) {
    while (size >= 2 && cross(hull[size - 2], hull[size - 1], point) <= kEpsilon) {
      --size;
    }
    hull[size++] = point;
  }
  const std::size_t lower_size = size + 1;
  for (std::size_t index = points.size() - 1; index-- > 0;) {
    const Point& point = points[index];
    while (size >= lower_size && cross(hull[size - 2], hull[size - 1], point) <= kEpsilon) {
      --size;
    }
    hull[size++] = point;
  }
  hull.resize(size - 1);  // the last point repeats the first
  return hull;
}

double width(const Polygon& polygon)
{
  const Polygon hull = convexHull(polygon);
  const std::size_t count = hull.size();
  if (count < 3) {
    return 0.0;
  }
  // For each hull edge, the farthest vertex (the antipodal caliper) only moves forward.
  double best = std::numeric_limits<double>::infinity();
  std::size_t farthest = 1;
  for (std::size_t index = 0; index < count; ++index) {
    const Point& a = hull[index];
    const Point& b = hull[(index + 1) % count];
    while (cross(a, b, hull[(farthest + 1) % count]) > cross(a, b, hull[farthest])) {
      farthest = (farthest + 1) % count;
    }
    best = std::min(best, cross(a, b, hull[farthest]) / (b - a).norm());
  }
  return best;
}

double distanceToBoundary(const Polygon& polygon, const Point& point)
{
  if (polygon.empty()) {
    return std::numeric_limits<double>::infinity();
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t index = 0; index < polygon.size(); ++index) {
    best = std::min(best, distanceToSegment(point, polygonEdge(polygon, index)));
  }
  return best;
}

bool polygonsIntersect(const Polygon& first, const Polygon& second)
{
  if (first.empty() || second.empty()) {
    return false;
  }
  for (std::size_t first_index = 0; first_index < first.size(); ++first_index) {
    const Segment first_edge = polygonEdge(first, first_index);
    for (std::size_t second_index = 0; second_index < second.size(); ++second_index) {
      if (segmentsIntersect(first_edge, polygonEdge(second, second_index))) {
        return true;
      }
    }
  }
  // No boundary contact: they intersect only when one lies wholly inside the other.
  return containsPoint(first, second.front()) || containsPoint(second, first.front());
}

Polygon offsetPolygon(const Polygon& polygon, double distance)
{
  const std::size_t count = polygon.size();
  if (count < 3 || distance == 0.0) {
    return polygon;
  }
  // Outward normal of each edge: a counter-clockwise polygon has its inside on the left.
  std::vector<Vector> normals(count, Vector::Zero());
  for (std::size_t index = 0; index < count; ++index) {
    const Vector along = polygon[(index + 1) % count] - polygon[index];
    const double length = along.norm();
    if (length > kEpsilon) {
      normals[index] = Vector(along.y(), -along.x()) / length;
    }
  }
  constexpr double kMitreLimit = 2.0;
  Polygon offset;
  offset.reserve(count);
  for (std::size_t index = 0; index < count; ++index) {
    const Vector& before = normals[(index + count - 1) % count];
    const Vector& after = normals[index];
    const Vector sum = before + after;
    const double cosine_plus_one = 1.0 + before.dot(after);
    Vector shift = Vector::Zero();
    // The mitre is 1 / cos(half the turn) = sqrt(2 / (1 + cos(turn))) long: at most kMitreLimit.
    if (cosine_plus_one >= 2.0 / (kMitreLimit * kMitreLimit)) {
      // The mitre point: on both offset edges' lines.
      shift = sum / cosine_plus_one;
    } else if (sum.norm() > kEpsilon) {
      shift = sum.normalized() * kMitreLimit;
    } else {
      shift = after;  // a zero-length neighbour edge or an edge folding straight back
    }
    offset.push_back(polygon[index] + distance * shift);
  }
  return offset;
}

}  // namespace ifar::geometry
