#include "planner/interaction/object_model.hpp"

#include <algorithm>
#include <cmath>

#include "planner/interaction/convex_polygon.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;

PlanStatus checkPolygon(const Polygon& polygon, const ConnectivitySettings& limits)
{
  if (polygon.size() < 3) {
    return PlanStatus::DegeneratePolygon;
  }
  for (const Point& vertex : polygon) {
    if (!std::isfinite(vertex.x()) || !std::isfinite(vertex.y())) {
      return PlanStatus::DegeneratePolygon;
    }
  }
  if (!geometry::isSimple(polygon) || geometry::area(polygon) < limits.minimum_area_m2 ||
      geometry::width(polygon) < limits.minimum_width_m) {
    return PlanStatus::DegeneratePolygon;
  }
  const Bounds bounds = boundsOf(polygon);
  const Point extent = bounds.maximum - bounds.minimum;
  if (extent.maxCoeff() > limits.local_layer_size_m) {
    return PlanStatus::ObjectTooLarge;
  }
  return PlanStatus::Found;
}

ObjectModelResult buildObjectModel(const Polygon& inflated_world, const PusherSettings& pusher,
                                   const ConnectivitySettings& limits, double clearance_m)
{
  ObjectModelResult result;
  result.status = checkPolygon(inflated_world, limits);
  if (result.status != PlanStatus::Found) {
    return result;
  }
  const Polygon hull = geometry::convexHull(inflated_world);
  const double hull_width = geometry::width(hull);
  const double shrink = std::min(pusher.inflation_m, 0.4 * hull_width);
  Polygon footprint = erodeConvex(hull, shrink);
  if (footprint.size() < 3) {
    result.status = PlanStatus::DegeneratePolygon;
    return result;
  }
  footprint = geometry::convexHull(footprint);  // drops collinear vertices left by clipping
  const Point centre = geometry::centroid(footprint);
  for (Point& vertex : footprint) {
    vertex -= centre;
  }
  result.model.footprint = footprint;
  result.model.travel_outline = dilateConvex(footprint, pusher.inflation_m + clearance_m);
  result.model.pose = geometry::Pose2{centre.x(), centre.y(), 0.0};
  result.model.depth_seen = shrink >= pusher.inflation_m;
  return result;
}

}  // namespace ifar::interaction
