#pragma once
// The vehicle-centred local layer: obstacle points rasterised into two binary images (background,
// movable), inflated by the vehicle's half width, traced into contours and simplified into world-frame
// polygons. OpenCV stays inside the .cpp.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/perception/classification.hpp"
#include "planner/perception/perception_settings.hpp"

namespace ifar::perception {

enum class ObstacleClass { Background, Movable };

/// Outer: the border of an inflated obstacle (the obstacle is inside the polygon). Hole: the border of
/// free space enclosed by an inflated obstacle (the free space is inside the polygon), e.g. a room.
enum class BoundaryKind { Outer, Hole };

struct LayerPolygon {
  geometry::Polygon vertices;  // world frame, counter-clockwise, not closed
  ObstacleClass obstacle_class = ObstacleClass::Background;
  BoundaryKind boundary = BoundaryKind::Outer;
};

/// The layer's raster: cells x cells square cells; cell (column, row) covers world
/// [origin.x + column * cell_size_m, +cell_size_m) x [origin.y + row * cell_size_m, +cell_size_m).
/// The origin sits on multiples of the cell size so the raster does not shift between frames.
struct LayerGrid {
  geometry::Point origin = geometry::Point::Zero();
  double cell_size_m = 0.15;
  int cells = 0;

  geometry::Point cellCentre(int column, int row) const;
  /// The (column, row) of the cell holding `point`; empty outside the grid.
  std::optional<std::pair<int, int>> cellOf(const geometry::Point& point) const;
  /// The row-major index (row * cells + column) of the cell holding `point`, as the layer's occupancy
  /// vectors are laid out; empty outside the grid.
  std::optional<std::size_t> indexOf(const geometry::Point& point) const;
  /// Size of one side in metres.
  double sideLength() const { return cells * cell_size_m; }
};

/// The grid of the given size centred (to the nearest cell) on `centre`.
LayerGrid makeLayerGrid(const geometry::Point& centre, const PerceptionSettings& settings);

struct LocalLayer {
  LayerGrid extent;  // the whole layer around the vehicle
  LayerGrid grid;    // the raster: the square part of `extent` that holds the points and their inflation
  std::vector<LayerPolygon> polygons;
  /// Inflated occupancy, row-major (index row * cells + column), 1 = occupied: for free-space queries.
  std::vector<std::uint8_t> background_occupancy;
  std::vector<std::uint8_t> movable_occupancy;
  std::size_t points_outside_layer = 0;
  std::size_t dropped_contours = 0;  // smaller than min_polygon_area_m2 or fewer than 3 vertices
};

/// The square part of `layer` (aligned to its cells) that holds every point of `points` inside `layer`,
/// grown by `margin_m`; `layer` itself when none is inside.
LayerGrid croppedLayerGrid(const LayerGrid& layer, const ClassifiedPoints& points, double margin_m);

/// Rasterises, inflates (disc of settings.inflation_radius_m), traces outer borders and holes
/// (Suzuki-Abe border following) and simplifies (Douglas-Peucker) each class.
LocalLayer buildLocalLayer(const ClassifiedPoints& points, const geometry::Point& centre,
                           const PerceptionSettings& settings);

}  // namespace ifar::perception
