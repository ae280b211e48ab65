#include "common/geometry/box_sweep.hpp"

#include <algorithm>

namespace ifar::geometry {

std::vector<std::pair<std::size_t, std::size_t>> overlappingBoxPairs(
    common::Span<const Eigen::AlignedBox2d> boxes, double tolerance)
{
  std::vector<std::size_t> order;
  order.reserve(boxes.size());
  for (std::size_t index = 0; index < boxes.size(); ++index) {
    if (!boxes[index].isEmpty()) {
      order.push_back(index);
    }
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].min().x() < boxes[b].min().x() || (boxes[a].min().x() == boxes[b].min().x() && a < b);
  });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::size_t> active;  // boxes whose x range may still reach the next ones
  for (const std::size_t index : order) {
    const Eigen::AlignedBox2d& box = boxes[index];
    active.erase(
        std::remove_if(active.begin(), active.end(),
                       [&](std::size_t other) { return boxes[other].max().x() + tolerance < box.min().x(); }),
        active.end());
    for (const std::size_t other : active) {
      const Eigen::AlignedBox2d& seen = boxes[other];
      if (seen.min().y() <= box.max().y() + tolerance && box.min().y() <= seen.max().y() + tolerance) {
        pairs.emplace_back(std::min(index, other), std::max(index, other));
      }
    }
    active.push_back(index);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace ifar::geometry
