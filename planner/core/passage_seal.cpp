#include "planner/core/passage_seal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ifar::planner {

std::optional<PassageSeal> sealPassage(const graph::ObstacleSet& obstacles, const geometry::Point& from,
                                       const geometry::Point& to, double inflation_m, double cell_size_m)
{
  const geometry::Point along = to - from;
  const double length = along.norm();
  if (!from.allFinite() || !to.allFinite() || !(cell_size_m > 0.0) || !(length > 0.0)) {
    return std::nullopt;
  }
  const geometry::Point direction = along / length;
  const double inflation = std::max(0.0, inflation_m);
  const double keep_clear_m = inflation + cell_size_m;
  // Integer steps of half a cell: fine enough to find the narrowest point of a channel a cell wide.
  const double step_m = 0.5 * cell_size_m;
  const auto steps = static_cast<int>(std::floor(length / step_m + 1e-9));
  geometry::Point narrowest_point = from;
  double narrowest = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= steps; ++step) {
    const double travel = static_cast<double>(step) * step_m;
    if (travel < keep_clear_m) {
      continue;
    }
    const geometry::Point point = from + travel * direction;
    if (obstacles.isBlocked(point)) {
      continue;
    }
    const double clearance = obstacles.distanceToBoundary(point);
    if (clearance < narrowest) {
      narrowest = clearance;
      narrowest_point = point;
    }
  }
  if (!std::isfinite(narrowest)) {  // no free point, or nothing narrow anywhere near
    return std::nullopt;
  }
  PassageSeal seal;
  seal.centre = narrowest_point;
  seal.half_width_m = narrowest;
  const geometry::Point across(-direction.y(), direction.x());
  // Across the free width and on into the inflation up to a cell short of the obstacle itself: the
  // obstacles here are the planner's picture (a box seen from one side is modelled thin, a raster edge
  // is a cell off), and a seal as wide as the picture's gap alone left the real lane open a little to one
  // side; the next path went through there and stalled again.
  const double deepest_m = std::max(0.0, inflation_m - cell_size_m);
  const auto sealable = [&](const geometry::Point& point) {
    return !obstacles.isBlocked(point) || obstacles.distanceToBoundary(point) <= deepest_m + 1e-9;
  };
  // At least the vehicle's width (twice the inflation) each side: the nearest obstacle may lie along the
  // segment, not across it (a segment that crosses a pushed bar seals just past the bar's inflation, 2 cm
  // from it, and a row of 3 cells would leave the gap beside the bar's end open, to be sealed again and
  // again).
  const double reach_m = std::max(seal.half_width_m, inflation) + inflation;
  const auto most_cells = static_cast<int>(std::ceil(reach_m / cell_size_m));
  const auto cellsToward = [&](double side) {
    int count = 0;
    while (count < most_cells &&
           sealable(seal.centre + side * static_cast<double>(count + 1) * cell_size_m * across)) {
      ++count;
    }
    return count;
  };
  const int right_cells = cellsToward(-1.0);
  const int left_cells = cellsToward(1.0);
  for (int offset = -right_cells; offset <= left_cells; ++offset) {
    seal.cells.push_back(seal.centre + static_cast<double>(offset) * cell_size_m * across);
  }
  seal.across.start = seal.centre - (static_cast<double>(right_cells) * cell_size_m + inflation) * across;
  seal.across.end = seal.centre + (static_cast<double>(left_cells) * cell_size_m + inflation) * across;
  return seal;
}

std::size_t removeEdgesThroughSeal(const PassageSeal& seal, graph::DvGraph& graph)
{
  std::vector<std::pair<graph::VertexId, graph::VertexId>> crossing;
  const std::vector<graph::Vertex>& slots = graph.vertexSlots();
  for (graph::VertexId id = 0; id < slots.size(); ++id) {
    if (!slots[id].alive) {
      continue;
    }
    for (const graph::VisibilityLink& link : graph.visibilityLinks(id)) {
      if (link.other > id && graph.contains(link.other) &&
          geometry::segmentsIntersect(geometry::Segment{slots[id].position, slots[link.other].position},
                                      seal.across)) {
        crossing.emplace_back(id, link.other);
      }
    }
  }
  for (const auto& [first, second] : crossing) {
    graph.removeVisibilityEdge(first, second);
  }
  return crossing.size();
}

}  // namespace ifar::planner
