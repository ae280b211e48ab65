#include "planner/perception/classification.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "planner/perception/cell_key.hpp"

namespace ifar::perception {

namespace {

struct TagCounts {
  std::uint32_t tagged = 0;
  std::uint32_t untagged = 0;
};

/// Each point's tag after its neighbourhood's vote (TagReading).
std::vector<bool> votedTags(common::Span<const WorldPoint> points, const TagReading& reading)
{
  std::vector<bool> tagged(points.size());
  for (std::size_t index = 0; index < points.size(); ++index) {
    tagged[index] = points[index].reflectivity >= reading.threshold;
  }
  if (!(reading.neighbourhood_m > 0.0)) {
    return tagged;
  }
  const auto cellOf = [&](const WorldPoint& point) {
    return std::pair<std::int64_t, std::int64_t>(
        static_cast<std::int64_t>(std::floor(point.position_world.x() / reading.neighbourhood_m)),
        static_cast<std::int64_t>(std::floor(point.position_world.y() / reading.neighbourhood_m)));
  };
  std::unordered_map<std::uint64_t, TagCounts> cells;
  cells.reserve(points.size());
  for (std::size_t index = 0; index < points.size(); ++index) {
    if (!points[index].position_world.allFinite()) {
      continue;
    }
    const auto [column, row] = cellOf(points[index]);
    TagCounts& counts = cells[packCellKey(column, row)];
    (tagged[index] ? counts.tagged : counts.untagged) += 1;
  }
  std::vector<bool> voted = tagged;
  for (std::size_t index = 0; index < points.size(); ++index) {
    if (!points[index].position_world.allFinite()) {
      continue;
    }
    const auto [column, row] = cellOf(points[index]);
    TagCounts around;
    for (std::int64_t dc = -1; dc <= 1; ++dc) {
      for (std::int64_t dr = -1; dr <= 1; ++dr) {
        const auto found = cells.find(packCellKey(column + dc, row + dr));
        if (found != cells.end()) {
          around.tagged += found->second.tagged;
          around.untagged += found->second.untagged;
        }
      }
    }
    const double agree = tagged[index] ? around.tagged : around.untagged;
    const double disagree = tagged[index] ? around.untagged : around.tagged;
    if (disagree > reading.overrule_ratio * agree) {
      voted[index] = !tagged[index];
    }
  }
  return voted;
}

}  // namespace

ClassifiedPoints classifyByReflectivity(common::Span<const WorldPoint> points, const TagReading& reading)
{
  const std::vector<bool> tagged = votedTags(points, reading);
  ClassifiedPoints result;
  result.background.reserve(points.size());
  result.background_heights_m.reserve(points.size());
  for (std::size_t index = 0; index < points.size(); ++index) {
    const WorldPoint& point = points[index];
    const geometry::Point ground(point.position_world.x(), point.position_world.y());
    const auto height = static_cast<float>(point.height_above_ground_m);
    if (tagged[index]) {
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
    const Eigen::AlignedBox2d box = geometry::boundingBox(polygon);
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
