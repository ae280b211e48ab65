#include "planner/perception/local_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace ifar::perception {
namespace {

/// How far the disc structuring element reaches along a row or column, in whole cells. Contours run
/// through the centres of border cells, half a cell inside the occupied area, so the disc reaches half a
/// cell further than the radius; the traced border then lies this many cells from the centre of the
/// cell that holds the point: on average, this many cells from the point itself.
int discReachCells(double radius_cells)
{
  return static_cast<int>(std::floor(radius_cells + 0.5));
}

/// The disc structuring element, `reach` cells to each side (see discReachCells).
cv::Mat discKernel(double radius_cells, int reach)
{
  const double limit = radius_cells + 0.5;
  cv::Mat kernel = cv::Mat::zeros(2 * reach + 1, 2 * reach + 1, CV_8UC1);
  for (int row = -reach; row <= reach; ++row) {
    for (int column = -reach; column <= reach; ++column) {
      if (std::hypot(row, column) <= limit) {
        kernel.at<std::uint8_t>(row + reach, column + reach) = 1;
      }
    }
  }
  return kernel;
}

/// Marks the cells of `points`; returns how many fell outside the grid.
std::size_t rasterise(const std::vector<geometry::Point>& points, const LayerGrid& grid, cv::Mat& image)
{
  std::size_t outside = 0;
  for (const geometry::Point& point : points) {
    const std::optional<std::pair<int, int>> cell = grid.cellOf(point);
    if (!cell) {
      ++outside;
      continue;
    }
    image.at<std::uint8_t>(cell->second, cell->first) = 255;
  }
  return outside;
}

/// Traces the inflated image into polygons. `outward_m` moves every traced border that far away from the
/// obstacle (into free space).
void traceContours(const cv::Mat& image, const LayerGrid& grid, ObstacleClass obstacle_class,
                   const PerceptionSettings& settings, double outward_m, LocalLayer& layer)
{
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  // Two-level hierarchy: outer borders at the top, holes (enclosed free space) below them.
  cv::findContours(image, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  const double epsilon_cells = settings.simplify_epsilon_m / grid.cell_size_m;
  std::vector<cv::Point> simplified;
  for (std::size_t index = 0; index < contours.size(); ++index) {
    cv::approxPolyDP(contours[index], simplified, epsilon_cells, true);
    LayerPolygon polygon;
    polygon.obstacle_class = obstacle_class;
    polygon.boundary = hierarchy[index][3] < 0 ? BoundaryKind::Outer : BoundaryKind::Hole;
    polygon.vertices.reserve(simplified.size());
    for (const cv::Point& cell : simplified) {
      polygon.vertices.push_back(grid.cellCentre(cell.x, cell.y));
    }
    if (polygon.vertices.size() < 3 || geometry::area(polygon.vertices) < settings.min_polygon_area_m2) {
      ++layer.dropped_contours;
      continue;
    }
    polygon.vertices = geometry::counterClockwise(std::move(polygon.vertices));
    if (outward_m != 0.0) {
      // An outer border grows outward; a hole (free space, the obstacle round it) shrinks.
      geometry::Polygon moved = geometry::offsetPolygon(
          polygon.vertices, polygon.boundary == BoundaryKind::Outer ? outward_m : -outward_m);
      if (geometry::isSimple(moved) || !geometry::isSimple(polygon.vertices)) {
        polygon.vertices = std::move(moved);
      }
    }
    layer.polygons.push_back(std::move(polygon));
  }
}

}  // namespace

geometry::Point LayerGrid::cellCentre(int column, int row) const
{
  return geometry::Point(origin.x() + (column + 0.5) * cell_size_m, origin.y() + (row + 0.5) * cell_size_m);
}

std::optional<std::pair<int, int>> LayerGrid::cellOf(const geometry::Point& point) const
{
  const double inverse_cell = 1.0 / cell_size_m;
  const double column = std::floor((point.x() - origin.x()) * inverse_cell);
  const double row = std::floor((point.y() - origin.y()) * inverse_cell);
  if (!(column >= 0.0 && row >= 0.0 && column < cells && row < cells)) {
    return std::nullopt;
  }
  return std::make_pair(static_cast<int>(column), static_cast<int>(row));
}

std::optional<std::size_t> LayerGrid::indexOf(const geometry::Point& point) const
{
  const std::optional<std::pair<int, int>> cell = cellOf(point);
  if (!cell) {
    return std::nullopt;
  }
  return static_cast<std::size_t>(cell->second) * static_cast<std::size_t>(cells) +
         static_cast<std::size_t>(cell->first);
}

LayerGrid makeLayerGrid(const geometry::Point& centre, const PerceptionSettings& settings)
{
  LayerGrid grid;
  grid.cell_size_m = settings.cell_size_m;
  grid.cells = settings.layerCells();
  const double half_cells = 0.5 * grid.cells;
  grid.origin = geometry::Point(std::round(centre.x() / grid.cell_size_m - half_cells) * grid.cell_size_m,
                                std::round(centre.y() / grid.cell_size_m - half_cells) * grid.cell_size_m);
  return grid;
}

LayerGrid croppedLayerGrid(const LayerGrid& layer, const ClassifiedPoints& points, double margin_m)
{
  geometry::Point minimum = geometry::Point::Constant(std::numeric_limits<double>::infinity());
  geometry::Point maximum = -minimum;
  const geometry::Point layer_max = layer.origin + geometry::Point::Constant(layer.sideLength());
  for (const std::vector<geometry::Point>* group : {&points.background, &points.movable}) {
    for (const geometry::Point& point : *group) {
      if (point.x() >= layer.origin.x() && point.y() >= layer.origin.y() && point.x() < layer_max.x() &&
          point.y() < layer_max.y()) {
        minimum = minimum.cwiseMin(point);
        maximum = maximum.cwiseMax(point);
      }
    }
  }
  if (!minimum.allFinite()) {
    return layer;  // nothing inside: the whole (free) layer
  }
  const auto cellOf = [&layer](double value, double origin) {
    return static_cast<int>(std::floor((value - origin) / layer.cell_size_m));
  };
  const int margin = static_cast<int>(std::ceil(margin_m / layer.cell_size_m));
  const int first_column = std::max(0, cellOf(minimum.x(), layer.origin.x()) - margin);
  const int first_row = std::max(0, cellOf(minimum.y(), layer.origin.y()) - margin);
  const int last_column = std::min(layer.cells - 1, cellOf(maximum.x(), layer.origin.x()) + margin);
  const int last_row = std::min(layer.cells - 1, cellOf(maximum.y(), layer.origin.y()) + margin);
  LayerGrid cropped = layer;
  cropped.cells = std::max(last_column - first_column, last_row - first_row) + 1;
  // Square, inside the layer: shift back where the larger side would run over the layer's far edge.
  const int column = std::min(first_column, layer.cells - cropped.cells);
  const int row = std::min(first_row, layer.cells - cropped.cells);
  cropped.origin = layer.origin + geometry::Point(column, row) * layer.cell_size_m;
  return cropped;
}

LocalLayer buildLocalLayer(const ClassifiedPoints& points, const geometry::Point& centre,
                           const PerceptionSettings& settings)
{
  LocalLayer layer;
  // The raster covers only the part of the layer that holds points (and their inflation): a layer as
  // large as the sensor's reach costs its full size only where the returns spread that far.
  const LayerGrid full = makeLayerGrid(centre, settings);
  layer.extent = full;
  layer.grid = croppedLayerGrid(full, points, settings.inflation_radius_m + 3.0 * settings.cell_size_m);
  const int cells = layer.grid.cells;
  const double radius_cells = settings.inflation_radius_m / settings.cell_size_m;
  const int reach = discReachCells(radius_cells);
  const cv::Mat kernel = discKernel(radius_cells, reach);
  // The disc reaches a whole number of cells: 2 of 0.15 m for a 0.35 m half width, so borders lie 0.30 m
  // out on average. With exact_inflation they are moved the rest of the way (up to half a cell either way).
  const double outward_m =
      settings.exact_inflation ? settings.inflation_radius_m - reach * settings.cell_size_m : 0.0;
  // Each class gets its own image: a movable object must not merge into the wall it leans on.
  const auto build_class = [&](const std::vector<geometry::Point>& class_points, ObstacleClass obstacle_class,
                               std::vector<std::uint8_t>& occupancy) {
    occupancy.assign(static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells), 0);
    if (class_points.empty()) {
      return;
    }
    // The image is a view of the occupancy vector (row-major, one byte a cell): no copy between them.
    cv::Mat image(cells, cells, CV_8UC1, occupancy.data());
    // The crop holds every point inside the layer, so what falls outside it is outside the layer.
    layer.points_outside_layer += rasterise(class_points, layer.grid, image);
    cv::dilate(image, image, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    traceContours(image, layer.grid, obstacle_class, settings, outward_m, layer);
    std::transform(occupancy.begin(), occupancy.end(), occupancy.begin(),
                   [](std::uint8_t cell) { return static_cast<std::uint8_t>(cell != 0 ? 1 : 0); });
  };
  build_class(points.background, ObstacleClass::Background, layer.background_occupancy);
  build_class(points.movable, ObstacleClass::Movable, layer.movable_occupancy);
  return layer;
}

}  // namespace ifar::perception
