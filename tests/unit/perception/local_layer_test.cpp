#include "planner/perception/local_layer.hpp"

#include <utility>

#include <gtest/gtest.h>

#include "planner/perception/synthetic/synthetic_scan.hpp"
#include "tests/unit/perception/inflated_box_matching.hpp"

namespace ifar::perception {
namespace {

using testing::mismatchToInflatedBox;
using testing::polygonsOf;

/// Points along the outline of `box` every 0.05 m.
std::vector<geometry::Point> outlinePoints(const geometry::Polygon& box)
{
  std::vector<geometry::Point> points;
  for (std::size_t index = 0; index < box.size(); ++index) {
    const geometry::Segment edge = geometry::polygonEdge(box, index);
    const int steps = static_cast<int>(std::ceil(edge.length() / 0.05));
    for (int step = 0; step < steps; ++step) {
      points.push_back(edge.start + (edge.end - edge.start) * (static_cast<double>(step) / steps));
    }
  }
  return points;
}

/// A 60 m layer (the grid numbers below are worked out for it).
PerceptionSettings sixtyMetreLayer()
{
  PerceptionSettings settings;
  settings.layer_size_m = 60.0;
  return settings;
}

TEST(LocalLayer, GridIsCentredAndSnappedToCells)
{
  const PerceptionSettings settings = sixtyMetreLayer();
  const LayerGrid grid = makeLayerGrid(geometry::Point(10.07, -3.0), settings);
  EXPECT_EQ(grid.cells, 400);
  EXPECT_NEAR(grid.sideLength(), 60.0, 1e-9);
  EXPECT_NEAR(grid.origin.x(), -19.95, 1e-9);  // 10.07 / 0.15 = 67.1 -> 67 cells, minus 200
  EXPECT_NEAR(grid.origin.y(), -33.0, 1e-9);
  const geometry::Point centre = grid.cellCentre(0, 0);
  EXPECT_NEAR(centre.x(), -19.875, 1e-9);
  EXPECT_NEAR(centre.y(), -32.925, 1e-9);
}

/// The layer of one background box and one movable box sampled along their outlines, each of which must
/// come out as one counter-clockwise polygon within two cells of the box inflated by the half width.
LocalLayer expectTwoInflatedBoxes(const geometry::Polygon& background_box,
                                  const geometry::Polygon& movable_box, const PerceptionSettings& settings)
{
  ClassifiedPoints points;
  points.background = outlinePoints(background_box);
  points.movable = outlinePoints(movable_box);
  const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
  const auto background = polygonsOf(layer, ObstacleClass::Background, BoundaryKind::Outer);
  const auto movable = polygonsOf(layer, ObstacleClass::Movable, BoundaryKind::Outer);
  EXPECT_EQ(background.size(), 1U);
  EXPECT_EQ(movable.size(), 1U);
  EXPECT_EQ(layer.polygons.size(), 2U);  // no holes: both interiors fill when inflated
  for (const auto& [found, box] : {std::pair{background, background_box}, std::pair{movable, movable_box}}) {
    if (!found.empty()) {
      EXPECT_LE(mismatchToInflatedBox(found[0].vertices, box, settings.inflation_radius_m),
                2.0 * settings.cell_size_m);
      EXPECT_GT(geometry::signedArea(found[0].vertices), 0.0);
    }
  }
  EXPECT_EQ(layer.points_outside_layer, 0U);
  return layer;
}

TEST(LocalLayer, InflatedBoxesMatchWithinTwoCells)
{
  expectTwoInflatedBoxes(synthetic::boxFootprint(4.0, 1.0, 2.0, 0.6),
                         synthetic::boxFootprint(-3.0, -2.0, 0.8, 0.8), PerceptionSettings{});
}

TEST(LocalLayer, EnclosedFreeSpaceIsAHole)
{
  PerceptionSettings settings;
  const geometry::Polygon room = synthetic::boxFootprint(0.0, 0.0, 6.0, 4.0);
  ClassifiedPoints points;
  points.background = outlinePoints(room);
  const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
  const auto outer = polygonsOf(layer, ObstacleClass::Background, BoundaryKind::Outer);
  const auto holes = polygonsOf(layer, ObstacleClass::Background, BoundaryKind::Hole);
  ASSERT_EQ(outer.size(), 1U);
  ASSERT_EQ(holes.size(), 1U);
  EXPECT_LE(mismatchToInflatedBox(outer[0].vertices, room, settings.inflation_radius_m),
            2.0 * settings.cell_size_m);
  // The hole is the room shrunk by the inflation radius: 5.3 m x 3.3 m.
  const geometry::Polygon shrunk = synthetic::boxFootprint(0.0, 0.0, 5.3, 3.3);
  for (const geometry::Point& vertex : holes[0].vertices) {
    EXPECT_LE(geometry::distanceToBoundary(shrunk, vertex), 2.0 * settings.cell_size_m);
  }
  EXPECT_NEAR(geometry::area(holes[0].vertices), 5.3 * 3.3, 5.3 * 3.3 * 0.1);
  EXPECT_GT(geometry::signedArea(holes[0].vertices), 0.0);
}

TEST(LocalLayer, OccupancyMarksInflatedCells)
{
  const PerceptionSettings settings = sixtyMetreLayer();
  ClassifiedPoints points;
  points.movable = {geometry::Point(1.0, 1.0)};
  const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
  const auto cell_index = [&](const geometry::Point& point) {
    const int column =
        static_cast<int>(std::floor((point.x() - layer.grid.origin.x()) / layer.grid.cell_size_m));
    const int row =
        static_cast<int>(std::floor((point.y() - layer.grid.origin.y()) / layer.grid.cell_size_m));
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(layer.grid.cells) +
           static_cast<std::size_t>(column);
  };
  const auto cells = static_cast<std::size_t>(layer.grid.cells);
  ASSERT_EQ(layer.movable_occupancy.size(), cells * cells);
  ASSERT_EQ(layer.background_occupancy.size(), cells * cells);
  EXPECT_EQ(layer.movable_occupancy[cell_index(geometry::Point(1.0, 1.0))], 1);
  EXPECT_EQ(layer.movable_occupancy[cell_index(geometry::Point(1.3, 1.0))], 1);  // within the radius
  EXPECT_EQ(layer.movable_occupancy[cell_index(geometry::Point(1.6, 1.0))], 0);
  EXPECT_EQ(layer.background_occupancy[cell_index(geometry::Point(1.0, 1.0))], 0);
  // A single point inflates to a disc of the vehicle's half width: one movable polygon.
  ASSERT_EQ(layer.polygons.size(), 1U);
  EXPECT_NEAR(geometry::width(layer.polygons[0].vertices), 0.7, 2.0 * settings.cell_size_m);
}

TEST(LocalLayer, TheRasterCoversOnlyThePointsAndTheirInflation)
{
  // A 200 m layer with two boxes 10 m apart: the raster is the square around them, not 1,334 cells a side,
  // and the polygons are what the whole layer gives.
  PerceptionSettings settings;
  settings.layer_size_m = 200.0;
  const LocalLayer layer = expectTwoInflatedBoxes(synthetic::boxFootprint(4.0, 1.0, 2.0, 0.6),
                                                  synthetic::boxFootprint(-6.0, 8.0, 0.8, 0.8), settings);
  EXPECT_EQ(layer.extent.cells, 1334);
  EXPECT_LT(layer.grid.cells, 120);  // 11.5 m of points plus the margin, in 0.15 m cells
  EXPECT_GE(layer.grid.origin.x(), layer.extent.origin.x());
  EXPECT_LE(layer.grid.origin.x(), -6.4 - settings.inflation_radius_m);
  EXPECT_LE(layer.grid.origin.y(), 0.7 - settings.inflation_radius_m);
  EXPECT_GE(layer.grid.origin.x() + layer.grid.sideLength(), 5.0 + settings.inflation_radius_m);
  EXPECT_GE(layer.grid.origin.y() + layer.grid.sideLength(), 8.4 + settings.inflation_radius_m);
}

TEST(LocalLayer, ACropNearTheLayersEdgeStaysInsideTheLayer)
{
  PerceptionSettings settings = sixtyMetreLayer();
  ClassifiedPoints points;
  points.background = {geometry::Point(29.9, 29.9), geometry::Point(20.0, 29.0)};
  const LayerGrid full = makeLayerGrid(geometry::Point(0.0, 0.0), settings);
  const LayerGrid crop = croppedLayerGrid(full, points, 1.0);
  EXPECT_LT(crop.cells, 100);
  EXPECT_NEAR(crop.origin.x() + crop.sideLength(), full.origin.x() + full.sideLength(), 1e-9);
  EXPECT_NEAR(crop.origin.y() + crop.sideLength(), full.origin.y() + full.sideLength(), 1e-9);
  EXPECT_LE(crop.origin.x(), 20.0 - 1.0);
  EXPECT_LE(crop.origin.y(), 29.0 - 1.0);
}

TEST(LocalLayer, PointsOutsideTheLayerAreCounted)
{
  const PerceptionSettings settings = sixtyMetreLayer();
  ClassifiedPoints points;
  points.background = {geometry::Point(31.0, 0.0), geometry::Point(0.0, -40.0), geometry::Point(5.0, 5.0)};
  const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
  EXPECT_EQ(layer.points_outside_layer, 2U);
  EXPECT_EQ(layer.polygons.size(), 1U);
}

TEST(LocalLayer, ObstacleCutByTheLayerEdgeKeepsItsInsidePart)
{
  const PerceptionSettings settings = sixtyMetreLayer();
  ClassifiedPoints points;
  points.background = {geometry::Point(29.95, 0.0)};  // the last column of a layer centred on the origin
  const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
  ASSERT_EQ(layer.polygons.size(), 1U);
  double min_x = 1e9;
  double max_x = -1e9;
  for (const geometry::Point& vertex : layer.polygons[0].vertices) {
    min_x = std::min(min_x, vertex.x());
    max_x = std::max(max_x, vertex.x());
  }
  EXPECT_NEAR(max_x, 29.925, 2.0 * settings.cell_size_m);  // the last cell centre
  EXPECT_NEAR(min_x, 29.95 - settings.inflation_radius_m, 2.0 * settings.cell_size_m);
}

TEST(LocalLayer, NoPointsNoPolygons)
{
  const LocalLayer layer =
      buildLocalLayer(ClassifiedPoints{}, geometry::Point(0.0, 0.0), PerceptionSettings{});
  EXPECT_TRUE(layer.polygons.empty());
  EXPECT_EQ(layer.dropped_contours, 0U);
}

TEST(LocalLayer, BordersLieTheInflationRadiusOutOnAverageWhereverTheBoxSitsInItsCells)
{
  // A 3 m x 2 m box at 40 positions spread over the cells: the disc reaches 2 whole cells (0.30 m) of
  // 0.15 m, and the traced border is moved the remaining 0.05 m, so the gap the planner sees beside an
  // obstacle is the vehicle's, not 0.1 m wider. Each side is off by at most half a cell.
  PerceptionSettings settings = sixtyMetreLayer();
  settings.exact_inflation = true;
  ASSERT_DOUBLE_EQ(settings.cell_size_m, 0.15);
  ASSERT_DOUBLE_EQ(settings.inflation_radius_m, 0.35);
  double sum = 0.0;
  int sides = 0;
  for (int position = 0; position < 40; ++position) {
    const double x0 = 0.0137 * position;  // 0 .. 0.53 m: more than three cells
    const double y0 = 0.0091 * position;
    ClassifiedPoints points;
    points.background = outlinePoints({{x0, y0}, {x0 + 3.0, y0}, {x0 + 3.0, y0 + 2.0}, {x0, y0 + 2.0}});
    const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
    const auto outer = polygonsOf(layer, ObstacleClass::Background, BoundaryKind::Outer);
    ASSERT_EQ(outer.size(), 1U) << position;
    const Eigen::AlignedBox2d box = geometry::boundingBox(outer[0].vertices);
    for (const double inflation :
         {x0 - box.min().x(), box.max().x() - (x0 + 3.0), y0 - box.min().y(), box.max().y() - (y0 + 2.0)}) {
      EXPECT_NEAR(inflation, settings.inflation_radius_m, 0.5 * settings.cell_size_m + 1e-9) << position;
      sum += inflation;
      ++sides;
    }
  }
  EXPECT_NEAR(sum / sides, settings.inflation_radius_m, 0.01);
}

TEST(LocalLayer, WithoutExactInflationBordersLieTheDiscsWholeCellsOut)
{
  // The same boxes with the shipped default: 2 cells of 0.15 m, 0.30 m on average, 0.05 m short.
  const PerceptionSettings settings = sixtyMetreLayer();
  ASSERT_FALSE(settings.exact_inflation);
  double sum = 0.0;
  int sides = 0;
  for (int position = 0; position < 40; ++position) {
    const double x0 = 0.0137 * position;
    ClassifiedPoints points;
    points.background = outlinePoints({{x0, 0.0}, {x0 + 3.0, 0.0}, {x0 + 3.0, 2.0}, {x0, 2.0}});
    const LocalLayer layer = buildLocalLayer(points, geometry::Point(0.0, 0.0), settings);
    const auto outer = polygonsOf(layer, ObstacleClass::Background, BoundaryKind::Outer);
    ASSERT_EQ(outer.size(), 1U) << position;
    const Eigen::AlignedBox2d box = geometry::boundingBox(outer[0].vertices);
    sum += (x0 - box.min().x()) + (box.max().x() - (x0 + 3.0));
    sides += 2;
  }
  EXPECT_NEAR(sum / sides, 2.0 * settings.cell_size_m, 0.01);
}

}  // namespace
}  // namespace ifar::perception
