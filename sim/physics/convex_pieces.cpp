#include "sim/physics/convex_pieces.hpp"

#include <algorithm>

namespace ifar::sim::physics {
namespace {

bool isStrictlyConvex(const geometry::Polygon& polygon)
{
  const std::size_t count = polygon.size();
  if (count < 3) {
    return false;
  }
  for (std::size_t index = 0; index < count; ++index) {
    const auto& previous = polygon[(index + count - 1) % count];
    const auto& current = polygon[index];
    const auto& next = polygon[(index + 1) % count];
    if (geometry::cross(previous, current, next) <= 0.0) {
      return false;
    }
  }
  return true;
}

bool pointInTriangle(const geometry::Point& point, const geometry::Point& a, const geometry::Point& b,
                     const geometry::Point& c)
{
  return geometry::cross(a, b, point) >= 0.0 && geometry::cross(b, c, point) >= 0.0 &&
         geometry::cross(c, a, point) >= 0.0;
}

}  // namespace

double signedPolygonArea(const geometry::Polygon& polygon)
{
  double twice_area = 0.0;
  for (std::size_t index = 0; index < polygon.size(); ++index) {
    const auto& current = polygon[index];
    const auto& next = polygon[(index + 1) % polygon.size()];
    twice_area += current.x() * next.y() - next.x() * current.y();
  }
  return 0.5 * twice_area;
}

std::vector<geometry::Polygon> convexPieces(const geometry::Polygon& polygon, std::size_t max_vertices,
                                            double min_area)
{
  geometry::Polygon ring = polygon;
  if (signedPolygonArea(ring) < 0.0) {
    std::reverse(ring.begin(), ring.end());
  }
  if (ring.size() <= max_vertices && isStrictlyConvex(ring)) {
    if (signedPolygonArea(ring) < min_area) {
      return {};
    }
    return {ring};
  }
  // Ear clipping: O(n^2), fine for the tens of vertices movable objects have.
  std::vector<geometry::Polygon> pieces;
  std::vector<std::size_t> remaining(ring.size());
  for (std::size_t index = 0; index < ring.size(); ++index) {
    remaining[index] = index;
  }
  std::size_t guard = 0;
  while (remaining.size() > 3 && guard < ring.size() * ring.size()) {
    ++guard;
    bool clipped = false;
    const std::size_t count = remaining.size();
    for (std::size_t position = 0; position < count; ++position) {
      const auto& a = ring[remaining[(position + count - 1) % count]];
      const auto& b = ring[remaining[position]];
      const auto& c = ring[remaining[(position + 1) % count]];
      if (geometry::cross(a, b, c) <= 0.0) {
        continue;  // reflex or flat corner: not an ear
      }
      bool contains_other = false;
      for (std::size_t other = 0; other < count && !contains_other; ++other) {
        const auto& point = ring[remaining[other]];
        if (point == a || point == b || point == c) {
          continue;
        }
        contains_other = pointInTriangle(point, a, b, c);
      }
      if (contains_other) {
        continue;
      }
      geometry::Polygon triangle{a, b, c};
      if (signedPolygonArea(triangle) >= min_area) {
        pieces.push_back(std::move(triangle));
      }
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(position));
      clipped = true;
      break;
    }
    if (!clipped) {
      // Drop a flat vertex (collinear or degenerate input) so clipping can go on.
      remaining.erase(remaining.begin());
    }
  }
  if (remaining.size() == 3) {
    geometry::Polygon triangle{ring[remaining[0]], ring[remaining[1]], ring[remaining[2]]};
    if (signedPolygonArea(triangle) >= min_area) {
      pieces.push_back(std::move(triangle));
    }
  }
  return pieces;
}

}  // namespace ifar::sim::physics
