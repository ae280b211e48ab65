#include "planner/core/object_seals.hpp"

#include <utility>

namespace ifar::planner {

void ObjectSeals::bind(std::int64_t object_id, const std::vector<geometry::Point>& gap,
                       const std::vector<geometry::Point>& cells)
{
  Seal& seal = seals_[object_id];
  seal.gap.insert(seal.gap.end(), gap.begin(), gap.end());
  seal.cells.insert(seal.cells.end(), cells.begin(), cells.end());
}

geometry::Polygon ObjectSeals::grown(std::int64_t object_id, const geometry::Polygon& outline) const
{
  const auto found = seals_.find(object_id);
  if (found == seals_.end() || outline.size() < 3) {
    return outline;
  }
  std::vector<geometry::Point> points(outline.begin(), outline.end());
  const double half = 0.5 * cell_size_m_;
  for (const geometry::Point& centre : found->second.gap) {
    for (const geometry::Point& corner : {geometry::Point(-half, -half), geometry::Point(half, -half),
                                          geometry::Point(half, half), geometry::Point(-half, half)}) {
      points.push_back(centre + corner);
    }
  }
  geometry::Polygon hull = geometry::convexHull(std::move(points));
  return hull.size() >= 3 ? hull : outline;
}

std::vector<geometry::Point> ObjectSeals::release(std::int64_t object_id)
{
  const auto found = seals_.find(object_id);
  if (found == seals_.end()) {
    return {};
  }
  std::vector<geometry::Point> cells = std::move(found->second.cells);
  seals_.erase(found);
  return cells;
}

}  // namespace ifar::planner
