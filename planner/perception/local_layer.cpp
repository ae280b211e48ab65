#include "planner/perception/local_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "common/geometry/segment.hpp"

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

/// Points sorted by the grid cell they fall in, over a window of the grid, so that the points near a cell
/// are found without looking at the others.
class CellBuckets {
 public:
  CellBuckets(const std::vector<geometry::Point>& points, const LayerGrid& grid, const cv::Rect& window)
      : window_(window), starts_(static_cast<std::size_t>(window.area()) + 1, 0)
  {
    std::vector<std::size_t> slots;
    slots.reserve(points.size());
    for (const geometry::Point& point : points) {
      const std::optional<std::size_t> slot = slotOf(grid.cellOf(point));
      slots.push_back(slot.value_or(kOutside));
      if (slot) {
        ++starts_[*slot + 1];
      }
    }
    std::partial_sum(starts_.begin(), starts_.end(), starts_.begin());
    points_.resize(starts_.back());
    std::vector<std::size_t> next(starts_.begin(), starts_.end() - 1);
    for (std::size_t index = 0; index < points.size(); ++index) {
      if (slots[index] != kOutside) {
        points_[next[slots[index]]++] = points[index];
      }
    }
  }

  /// The point nearest `centre` no farther than `reach`, among those in the cells at most `reach_cells`
  /// columns and rows from `cell`.
  std::optional<geometry::Point> nearest(const geometry::Point& centre, const cv::Point& cell,
                                         int reach_cells, double reach) const
  {
    std::optional<geometry::Point> found;
    double found_squared = reach * reach;
    const cv::Rect around =
        cv::Rect(cell.x - reach_cells, cell.y - reach_cells, 2 * reach_cells + 1, 2 * reach_cells + 1) &
        window_;
    for (int row = around.y; row < around.y + around.height; ++row) {
      const std::size_t first = slotIn(around.x, row);
      for (std::size_t index = starts_[first];
           index < starts_[first + static_cast<std::size_t>(around.width)]; ++index) {
        const double squared = (points_[index] - centre).squaredNorm();
        if (squared <= found_squared) {
          found = points_[index];
          found_squared = squared;
        }
      }
    }
    return found;
  }

 private:
  static constexpr std::size_t kOutside = std::numeric_limits<std::size_t>::max();

  std::size_t slotIn(int column, int row) const
  {
    return static_cast<std::size_t>(row - window_.y) * static_cast<std::size_t>(window_.width) +
           static_cast<std::size_t>(column - window_.x);
  }

  std::optional<std::size_t> slotOf(const std::optional<std::pair<int, int>>& cell) const
  {
    if (!cell || !window_.contains(cv::Point(cell->first, cell->second))) {
      return std::nullopt;
    }
    return slotIn(cell->first, cell->second);
  }

  cv::Rect window_;
  std::vector<std::size_t> starts_;  ///< per cell of the window (row-major), where its points begin
  std::vector<geometry::Point> points_;
};

/// An object's grown cells next to the wall's grown cells where the wall return and the object return
/// that grew them (the nearest of each class) are closer together than `vehicle_width_m` and the cell
/// lies across the gap between them: there the two outlines would share an edge along a way the vehicle
/// does not fit through. Where the returns are farther apart the cells are left out, so a gap the vehicle
/// fits through stays open whatever cells the returns fall in; where the object runs along the wall (the
/// cell beside the line between the two returns, not across it) the object's cells stay the object's.
std::vector<cv::Point> narrowSeamCells(const ClassifiedPoints& points, const LayerGrid& grid,
                                       const cv::Mat& background, const cv::Mat& movable, int grown_cells,
                                       double inflation_radius_m, double vehicle_width_m)
{
  // Objects are few and near the vehicle while the layer can hold a map's walls: only the part of the
  // images round the objects' grown cells (and a cell of the wall's beyond) is looked at.
  std::vector<cv::Point> object_cells;
  object_cells.reserve(points.movable.size());
  for (const geometry::Point& point : points.movable) {
    if (const std::optional<std::pair<int, int>> cell = grid.cellOf(point)) {
      object_cells.emplace_back(cell->first, cell->second);
    }
  }
  std::vector<cv::Point> seam_cells;
  if (object_cells.empty()) {
    return seam_cells;
  }
  const int margin = grown_cells + 2;
  const cv::Rect objects_box = cv::boundingRect(object_cells);
  const cv::Rect region = cv::Rect(objects_box.x - margin, objects_box.y - margin,
                                   objects_box.width + 2 * margin, objects_box.height + 2 * margin) &
                          cv::Rect(0, 0, movable.cols, movable.rows);
  cv::Mat beside;
  cv::dilate(background(region), beside, cv::Mat::ones(3, 3, CV_8UC1), cv::Point(-1, -1), 1,
             cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::findNonZero(beside & movable(region), seam_cells);
  std::vector<cv::Point> narrow;
  if (seam_cells.empty()) {
    return narrow;
  }
  for (cv::Point& cell : seam_cells) {
    cell += region.tl();
  }
  // A grown cell's centre lies within the disc's reach (the radius and half a cell) of the centre of the
  // cell whose return grew it, the return within half a diagonal of that, and the wall's grown cell is a
  // neighbour of the seam cell: the returns that grew the seam lie within this of it.
  const double reach = inflation_radius_m + 3.0 * grid.cell_size_m;
  const int reach_cells = static_cast<int>(std::ceil(reach / grid.cell_size_m));
  // Across the gap, the line between the two returns passes through the cell: within half its diagonal.
  const double across_tolerance = std::sqrt(0.5) * grid.cell_size_m;
  const cv::Rect window = cv::boundingRect(seam_cells);
  const cv::Rect searched = cv::Rect(window.x - reach_cells, window.y - reach_cells,
                                     window.width + 2 * reach_cells, window.height + 2 * reach_cells) &
                            cv::Rect(0, 0, movable.cols, movable.rows);
  const CellBuckets walls(points.background, grid, searched);
  const CellBuckets objects(points.movable, grid, searched);
  const double width_squared = vehicle_width_m * vehicle_width_m;
  for (const cv::Point& cell : seam_cells) {
    const geometry::Point centre = grid.cellCentre(cell.x, cell.y);
    const std::optional<geometry::Point> wall = walls.nearest(centre, cell, reach_cells, reach);
    const std::optional<geometry::Point> object = objects.nearest(centre, cell, reach_cells, reach);
    if (wall && object && (*wall - *object).squaredNorm() < width_squared &&
        geometry::distanceToSegment(centre, geometry::Segment{*wall, *object}) <= across_tolerance) {
      narrow.push_back(cell);
    }
  }
  return narrow;
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
  const auto dilate_class = [&](const std::vector<geometry::Point>& class_points,
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
  };
  dilate_class(points.background, layer.background_occupancy);
  dilate_class(points.movable, layer.movable_occupancy);
  cv::Mat background(cells, cells, CV_8UC1, layer.background_occupancy.data());
  cv::Mat movable(cells, cells, CV_8UC1, layer.movable_occupancy.data());
  if (!points.background.empty()) {
    // Where the grown images of the two classes touch, their outlines would only share an edge, and a
    // way along it (of no width) would pass for free. Where wall and object are closer together than the
    // vehicle is wide, the wall's outline takes in the object's cells next to it, so the two overlap and
    // that way is closed; a gap the vehicle fits through stays open. Those cells are drawn into the wall's
    // image for its tracing only: they are the object's, and its own outline is traced as seen (push
    // planning takes the object's size from it).
    std::vector<cv::Point> drawn;
    for (const cv::Point& cell :
         narrowSeamCells(points, layer.grid, background, movable, reach, settings.inflation_radius_m,
                         2.0 * settings.inflation_radius_m)) {
      if (background.at<std::uint8_t>(cell) == 0) {
        background.at<std::uint8_t>(cell) = 255;
        drawn.push_back(cell);
      }
    }
    traceContours(background, layer.grid, ObstacleClass::Background, settings, outward_m, layer);
    for (const cv::Point& cell : drawn) {
      background.at<std::uint8_t>(cell) = 0;
    }
  }
  if (!points.movable.empty()) {
    traceContours(movable, layer.grid, ObstacleClass::Movable, settings, outward_m, layer);
  }
  for (std::vector<std::uint8_t>* occupancy : {&layer.background_occupancy, &layer.movable_occupancy}) {
    std::transform(occupancy->begin(), occupancy->end(), occupancy->begin(),
                   [](std::uint8_t cell) { return static_cast<std::uint8_t>(cell != 0 ? 1 : 0); });
  }
  return layer;
}

}  // namespace ifar::perception
