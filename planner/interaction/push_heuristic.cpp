#include "planner/interaction/push_heuristic.hpp"

#include "planner/interaction/body_frame.hpp"
#include "planner/interaction/convex_polygon.hpp"

namespace ifar::interaction {

double PushHeuristic::costToGo(const geometry::Pose2& pose, const PushGoalRegion& region) const
{
  const geometry::Polygon inside = clipConvex(transformed(footprint_, pose), region.window);
  if (inside.size() < 3) {
    return 0.0;
  }
  return geometry::width(inside) * cost_per_metre_;
}

}  // namespace ifar::interaction
