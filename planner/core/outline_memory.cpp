#include "planner/core/outline_memory.hpp"

#include <vector>

namespace ifar::planner {

geometry::Polygon OutlineMemory::remember(std::int64_t id, const geometry::Polygon& outline,
                                          const geometry::Point& vehicle)
{
  if (!enabled() || outline.size() < 3) {
    return outline;
  }
  const bool at_object = geometry::containsPoint(outline, vehicle) ||
                         geometry::distanceToBoundary(outline, vehicle) <= restart_distance_m_;
  const auto remembered = hulls_.find(id);
  if (at_object || remembered == hulls_.end()) {
    geometry::Polygon hull =
        geometry::convexHull(std::vector<geometry::Point>(outline.begin(), outline.end()));
    hulls_[id] = hull;
    return hull;
  }
  std::vector<geometry::Point> points(remembered->second.begin(), remembered->second.end());
  points.insert(points.end(), outline.begin(), outline.end());
  remembered->second = geometry::convexHull(std::move(points));
  return remembered->second;
}

}  // namespace ifar::planner
