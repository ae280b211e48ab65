#include "planner/interaction/free_space_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/geometry/segment.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;

FreeSpaceRaster::FreeSpaceRaster(const Bounds& window, double resolution_m)
    : window_(window),
      resolution_(resolution_m),
      columns_(
          std::max(1, static_cast<int>(std::ceil((window.maximum.x() - window.minimum.x()) / resolution_m)))),
      rows_(
          std::max(1, static_cast<int>(std::ceil((window.maximum.y() - window.minimum.y()) / resolution_m)))),
      cells_(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_), 0)
{
}

void FreeSpaceRaster::fill(const Polygon& polygon, std::uint8_t layer)
{
  const std::size_t count = polygon.size();
  if (count < 3) {
    return;
  }
  const Bounds bounds = boundsOf(polygon);
  const int first_row =
      std::max(0, static_cast<int>(std::floor((bounds.minimum.y() - window_.minimum.y()) / resolution_)));
  const int last_row = std::min(
      rows_ - 1, static_cast<int>(std::ceil((bounds.maximum.y() - window_.minimum.y()) / resolution_)));
  std::vector<double> crossings;
  for (int row = first_row; row <= last_row; ++row) {
    const double y = window_.minimum.y() + (row + 0.5) * resolution_;
    crossings.clear();
    for (std::size_t index = 0; index < count; ++index) {
      const Point& a = polygon[index];
      const Point& b = polygon[(index + 1) % count];
      if ((a.y() <= y) != (b.y() <= y)) {
        crossings.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t pair = 0; pair + 1 < crossings.size(); pair += 2) {
      const int first_column = std::max(
          0, static_cast<int>(std::ceil((crossings[pair] - window_.minimum.x()) / resolution_ - 0.5)));
      const int last_column = std::min(
          columns_ - 1,
          static_cast<int>(std::floor((crossings[pair + 1] - window_.minimum.x()) / resolution_ - 0.5)));
      for (int column = first_column; column <= last_column; ++column) {
        cells_[index(row, column)] |= layer;
      }
    }
  }
}

namespace {

/// A polygon edge from `start` to `end` with what geometry::closestPointOnSegment works out of it for
/// every query, worked out once: a pushed object's outline is measured from every cell near it, at
/// every pose the push search judges.
struct MeasuredEdge {
  Point start;
  Point end;
  geometry::Vector direction;
  double squared_length;
};

std::vector<MeasuredEdge> measuredEdges(const Polygon& polygon)
{
  std::vector<MeasuredEdge> edges;
  edges.reserve(polygon.size());
  for (std::size_t index = 0, previous = polygon.size() - 1; index < polygon.size(); previous = index++) {
    const Point& a = polygon[previous];
    const Point& b = polygon[index];
    const geometry::Vector direction = b - a;
    edges.push_back(MeasuredEdge{a, b, direction, direction.squaredNorm()});
  }
  return edges;
}

/// How far `point` lies outside the polygon of `edges` (even-odd rule), 0 inside or within kEpsilon of
/// an edge. One pass over the edges with squared distances, each as closestPointOnSegment gives it.
double distanceOutside(const std::vector<MeasuredEdge>& edges, const Point& point)
{
  double nearest_squared = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (const MeasuredEdge& edge : edges) {
    const Point closest =
        edge.squared_length <= geometry::kEpsilon * geometry::kEpsilon
            ? edge.start
            : Point(edge.start +
                    std::clamp((point - edge.start).dot(edge.direction) / edge.squared_length, 0.0, 1.0) *
                        edge.direction);
    nearest_squared = std::min(nearest_squared, (point - closest).squaredNorm());
    if ((edge.start.y() > point.y()) != (edge.end.y() > point.y()) &&
        point.x() < edge.start.x() + (point.y() - edge.start.y()) * edge.direction.x() / edge.direction.y()) {
      inside = !inside;
    }
  }
  const double nearest = std::sqrt(nearest_squared);
  return inside || nearest <= geometry::kEpsilon ? 0.0 : nearest;
}

}  // namespace

std::vector<FreeSpaceRaster::CellDistance> FreeSpaceRaster::cellDistancesNear(const Polygon& polygon,
                                                                              double distance_m) const
{
  std::vector<CellDistance> near;
  if (polygon.size() < 3) {
    return near;
  }
  const Bounds bounds = boundsOf(polygon);
  const double reach = std::max(0.0, distance_m);
  const auto cellRange = [&](double low, double high, double origin, int count) {
    return std::pair<int, int>{
        std::max(0, static_cast<int>(std::floor((low - reach - origin) / resolution_))),
        std::min(count - 1, static_cast<int>(std::floor((high + reach - origin) / resolution_)))};
  };
  const auto [first_row, last_row] =
      cellRange(bounds.minimum.y(), bounds.maximum.y(), window_.minimum.y(), rows_);
  const auto [first_column, last_column] =
      cellRange(bounds.minimum.x(), bounds.maximum.x(), window_.minimum.x(), columns_);
  const std::vector<MeasuredEdge> edges = measuredEdges(polygon);
  if (last_row >= first_row && last_column >= first_column) {
    near.reserve(static_cast<std::size_t>(last_row - first_row + 1) *
                 static_cast<std::size_t>(last_column - first_column + 1));
  }
  for (int row = first_row; row <= last_row; ++row) {
    for (int column = first_column; column <= last_column; ++column) {
      const Point centre(window_.minimum.x() + (column + 0.5) * resolution_,
                         window_.minimum.y() + (row + 0.5) * resolution_);
      const double outside = distanceOutside(edges, centre);
      if (outside <= reach) {
        near.push_back(CellDistance{index(row, column), outside});
      }
    }
  }
  return near;
}

std::vector<std::size_t> FreeSpaceRaster::cellsNear(const Polygon& polygon, double distance_m) const
{
  const std::vector<CellDistance> near = cellDistancesNear(polygon, distance_m);
  std::vector<std::size_t> covered;
  covered.reserve(near.size());
  for (const CellDistance& cell : near) {
    covered.push_back(cell.cell);
  }
  return covered;
}

void FreeSpaceRaster::mark(const std::vector<std::size_t>& cells, std::uint8_t layer)
{
  for (const std::size_t cell : cells) {
    cells_[cell] |= layer;
  }
}

bool FreeSpaceRaster::onBorder(std::size_t cell) const
{
  const auto row = static_cast<int>(cell / static_cast<std::size_t>(columns_));
  const auto column = static_cast<int>(cell % static_cast<std::size_t>(columns_));
  return row == 0 || row == rows_ - 1 || column == 0 || column == columns_ - 1;
}

std::optional<std::size_t> FreeSpaceRaster::nearestFree(const Point& point, std::uint8_t blocked_layers,
                                                        int radius_cells) const
{
  return nearestCell(point, radius_cells,
                     [&](std::size_t cell) { return (cells_[cell] & blocked_layers) == 0; });
}

std::optional<std::size_t> FreeSpaceRaster::nearestFree(const Point& point, std::uint8_t blocked_layers,
                                                        int radius_cells,
                                                        const std::vector<std::size_t>& closed_sorted) const
{
  return nearestCell(point, radius_cells, [&](std::size_t cell) {
    return (cells_[cell] & blocked_layers) == 0 &&
           !std::binary_search(closed_sorted.begin(), closed_sorted.end(), cell);
  });
}

std::vector<std::size_t> FreeSpaceRaster::borderCells() const
{
  // Round the window from cell (row 0, column 0): each cell follows a 4-neighbour, so a run of free
  // cells in this order is one stretch of the window's edge.
  std::vector<std::size_t> border;
  if (rows_ == 1 || columns_ == 1) {
    for (std::size_t cell = 0; cell < cells_.size(); ++cell) {
      border.push_back(cell);
    }
    return border;
  }
  for (int column = 0; column < columns_; ++column) {
    border.push_back(index(0, column));
  }
  for (int row = 1; row < rows_; ++row) {
    border.push_back(index(row, columns_ - 1));
  }
  for (int column = columns_ - 2; column >= 0; --column) {
    border.push_back(index(rows_ - 1, column));
  }
  for (int row = rows_ - 2; row >= 1; --row) {
    border.push_back(index(row, 0));
  }
  return border;
}

std::vector<int> FreeSpaceRaster::labelComponents(std::uint8_t blocked_layers, int& component_count) const
{
  std::vector<int> labels(cells_.size(), -1);
  component_count = 0;
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < cells_.size(); ++seed) {
    if ((cells_[seed] & blocked_layers) != 0 || labels[seed] >= 0) {
      continue;
    }
    labels[seed] = component_count;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::size_t cell = stack.back();
      stack.pop_back();
      const auto column = static_cast<int>(cell % static_cast<std::size_t>(columns_));
      forEachFreeNeighbour(cell, column, blocked_layers, [&](std::size_t next, int /*next_column*/) {
        if (labels[next] < 0) {
          labels[next] = component_count;
          stack.push_back(next);
        }
      });
    }
    ++component_count;
  }
  return labels;
}

std::optional<std::size_t> FreeSpaceRaster::cellOf(const Point& point) const
{
  const int column = static_cast<int>(std::floor((point.x() - window_.minimum.x()) / resolution_));
  const int row = static_cast<int>(std::floor((point.y() - window_.minimum.y()) / resolution_));
  if (column < 0 || column >= columns_ || row < 0 || row >= rows_) {
    return std::nullopt;
  }
  return index(row, column);
}

std::optional<std::size_t> FreeSpaceRaster::nearestLabelled(const Point& point,
                                                            const std::vector<int>& labels,
                                                            int radius_cells) const
{
  return nearestCell(point, radius_cells, [&](std::size_t cell) { return labels[cell] >= 0; });
}

std::optional<std::size_t> FreeSpaceRaster::nearestCell(const Point& point, int radius_cells,
                                                        const std::function<bool(std::size_t)>& accept) const
{
  const int column = static_cast<int>(std::floor((point.x() - window_.minimum.x()) / resolution_));
  const int row = static_cast<int>(std::floor((point.y() - window_.minimum.y()) / resolution_));
  for (int ring = 0; ring <= radius_cells; ++ring) {
    for (int dr = -ring; dr <= ring; ++dr) {
      for (int dc = -ring; dc <= ring; ++dc) {
        if (std::max(std::abs(dr), std::abs(dc)) != ring) {
          continue;
        }
        const int r = row + dr;
        const int c = column + dc;
        if (r < 0 || r >= rows_ || c < 0 || c >= columns_) {
          continue;
        }
        const std::size_t cell = index(r, c);
        if (accept(cell)) {
          return cell;
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace ifar::interaction
