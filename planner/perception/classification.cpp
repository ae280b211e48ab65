#include "planner/perception/classification.hpp"

#include <Eigen/Geometry>

namespace ifar::perception {

ClassifiedPoints classifyByReflectivity(common::Span<const WorldPoint> points, float threshold)
{
  ClassifiedPoints result;
  result.background.reserve(points.size());
  result.background_heights_m.reserve(points.size());
  for (const WorldPoint& point : points) {
    const geometry::Point ground(point.position_world.x(), point.position_world.y());
    const auto height = static_cast<float>(point.height_above_ground_m);
    if (point.reflectivity >= threshold) {
      result.movable.push_back(ground);
      result.movable_heights_m.push_back(height);
    } else {
      result.background.push_back(ground);
      result.background_heights_m.push_back(height);
    }
  }
  return result;
}

ClassifiedPoints classifyByDetector(common::Span<const WorldPoint> points,
                                    common::Span<const geometry::Polygon> detector_polygons)
{
  // Bounding boxes first: most points are far from every detected object.
  std::vector<Eigen::AlignedBox2d> boxes;
  boxes.reserve(detector_polygons.size());
  for (const geometry::Polygon& polygon : detector_polygons) {
    Eigen::AlignedBox2d box;
    for (const geometry::Point& vertex : polygon) {
      box.extend(vertex);
    }
    // Padded so points on a box edge reach the exact (tolerant) polygon test.
    const geometry::Vector padding = geometry::Vector::Constant(geometry::kEpsilon);
    boxes.push_back(box.isEmpty() ? box : Eigen::AlignedBox2d(box.min() - padding, box.max() + padding));
  }
  ClassifiedPoints result;
  result.background.reserve(points.size());
  result.background_heights_m.reserve(points.size());
  for (const WorldPoint& point : points) {
    const geometry::Point ground(point.position_world.x(), point.position_world.y());
    bool movable = false;
    for (std::size_t index = 0; index < detector_polygons.size() && !movable; ++index) {
      movable = boxes[index].contains(ground) && geometry::containsPoint(detector_polygons[index], ground);
    }
    const auto height = static_cast<float>(point.height_above_ground_m);
    if (movable) {
      result.movable.push_back(ground);
      result.movable_heights_m.push_back(height);
    } else {
      result.background.push_back(ground);
      result.background_heights_m.push_back(height);
    }
  }
  return result;
}

}  // namespace ifar::perception
