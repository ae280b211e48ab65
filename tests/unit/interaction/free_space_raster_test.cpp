#include "planner/interaction/free_space_raster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "common/geometry/polygon.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;
using geometry::Polygon;

// A 1 m square window of 0.1 m cells: cell (row, column) has its centre at (0.05 + 0.1 column, 0.05 + 0.1
// row).
FreeSpaceRaster unitWindow()
{
  Bounds window;
  window.minimum = Point(0.0, 0.0);
  window.maximum = Point(1.0, 1.0);
  return FreeSpaceRaster(window, 0.1);
}

std::size_t cellAt(int row, int column)
{
  return static_cast<std::size_t>(row * 10 + column);
}

const Polygon kSquare = {Point(0.3, 0.3), Point(0.7, 0.3), Point(0.7, 0.7), Point(0.3, 0.7)};

TEST(FreeSpaceRasterTest, CellsInsideAreAtDistanceZeroAndTheRingAtItsCentresDistance)
{
  const FreeSpaceRaster raster = unitWindow();
  const std::vector<FreeSpaceRaster::CellDistance> near = raster.cellDistancesNear(kSquare, 0.06);
  // 4 x 4 centres inside, and the 4 x 4 edge neighbours 0.05 m out; the corner cells are 0.071 m out.
  ASSERT_EQ(near.size(), 32U);
  const auto distanceOf = [&](std::size_t cell) {
    const auto found = std::find_if(near.begin(), near.end(), [&](const FreeSpaceRaster::CellDistance& item) {
      return item.cell == cell;
    });
    return found == near.end() ? -1.0 : found->distance_m;
  };
  EXPECT_DOUBLE_EQ(distanceOf(cellAt(4, 4)), 0.0);
  EXPECT_NEAR(distanceOf(cellAt(2, 4)), 0.05, 1e-12);
  EXPECT_NEAR(distanceOf(cellAt(5, 7)), 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(distanceOf(cellAt(2, 2)), -1.0);
  EXPECT_EQ(raster.cellDistancesNear(kSquare, 0.1).size(), 36U);
  EXPECT_EQ(raster.cellsNear(kSquare, 0.0).size(), 16U);
}

TEST(FreeSpaceRasterTest, CellsNearAgreeWithThePolygonsOwnContainmentAndDistance)
{
  // Concave (an L), so the even-odd rule and the nearest edge are both exercised.
  const Polygon ell = {Point(0.12, 0.08), Point(0.88, 0.14), Point(0.81, 0.37),
                       Point(0.41, 0.33), Point(0.47, 0.91), Point(0.16, 0.86)};
  const FreeSpaceRaster raster = unitWindow();
  for (const double reach : {0.0, 0.04, 0.13}) {
    const std::vector<FreeSpaceRaster::CellDistance> near = raster.cellDistancesNear(ell, reach);
    std::vector<std::size_t> expected;
    for (int row = 0; row < 10; ++row) {
      for (int column = 0; column < 10; ++column) {
        const Point centre(0.05 + 0.1 * column, 0.05 + 0.1 * row);
        const bool inside = geometry::locatePoint(ell, centre) != geometry::Containment::Outside;
        const double distance = inside ? 0.0 : geometry::distanceToBoundary(ell, centre);
        if (distance <= reach) {
          expected.push_back(cellAt(row, column));
          const auto found = std::find_if(
              near.begin(), near.end(),
              [&](const FreeSpaceRaster::CellDistance& item) { return item.cell == cellAt(row, column); });
          ASSERT_NE(found, near.end()) << "reach " << reach << " row " << row << " column " << column;
          EXPECT_NEAR(found->distance_m, distance, 1e-12);
        }
      }
    }
    EXPECT_EQ(raster.cellsNear(ell, reach), expected) << "reach " << reach;
  }
}

// Every cell a search visits, in order, with its steps.
using Visits = std::vector<std::pair<std::size_t, int>>;

TEST(FreeSpaceRasterTest, ASearchWithClosedCellsVisitsWhatTheRasterWithThoseCellsMarkedDoes)
{
  // A wall across the window with a gap at columns 6-7, and an object's cells that close part of the gap.
  FreeSpaceRaster raster = unitWindow();
  raster.fill({Point(0.0, 0.42), Point(0.58, 0.42), Point(0.58, 0.48), Point(0.0, 0.48)},
              FreeSpaceRaster::kObstacle);
  raster.fill({Point(0.82, 0.42), Point(1.0, 0.42), Point(1.0, 0.48), Point(0.82, 0.48)},
              FreeSpaceRaster::kObstacle);
  const std::vector<std::size_t> closed = {cellAt(4, 6), cellAt(5, 6), cellAt(5, 5)};
  FreeSpaceRaster marked = raster;
  marked.mark(closed, FreeSpaceRaster::kMovable);
  const auto search = [](const FreeSpaceRaster& on, const auto& run) {
    Visits visits;
    run(on, [&](std::size_t cell, int steps) {
      visits.emplace_back(cell, steps);
      return false;
    });
    return visits;
  };
  const std::uint8_t both = FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable;
  const Visits expected = search(marked, [&](const FreeSpaceRaster& on, const auto& visit) {
    on.searchFrom(cellAt(0, 0), both, visit);
  });
  // Only column 7 of the gap stays open (8 wall cells, 3 closed): the far side is reached through it,
  // 12 steps to cell (5, 7).
  ASSERT_EQ(expected.size(), 100U - 8U - 3U);
  const auto far_side = std::find_if(expected.begin(), expected.end(),
                                     [](const auto& visit) { return visit.first == cellAt(5, 7); });
  ASSERT_NE(far_side, expected.end());
  EXPECT_EQ(far_side->second, 12);
  // One scratch for several searches of different rasters: what one search reached must not leak into
  // the next.
  FreeSpaceRaster::SearchScratch scratch;
  const FreeSpaceRaster other = unitWindow();
  for (int round = 0; round < 3; ++round) {
    EXPECT_EQ(search(raster,
                     [&](const FreeSpaceRaster& on, const auto& visit) {
                       on.searchFrom(cellAt(0, 0), FreeSpaceRaster::kObstacle, closed, scratch, visit);
                     }),
              expected)
        << "round " << round;
    EXPECT_EQ(search(other,
                     [&](const FreeSpaceRaster& on, const auto& visit) {
                       on.searchFrom(cellAt(9, 9), FreeSpaceRaster::kObstacle, {}, scratch, visit);
                     })
                  .size(),
              100U);
  }
  // A start on a closed cell reaches nothing.
  EXPECT_TRUE(search(raster, [&](const FreeSpaceRaster& on, const auto& visit) {
                on.searchFrom(cellAt(5, 5), FreeSpaceRaster::kObstacle, closed, scratch, visit);
              }).empty());
}

TEST(FreeSpaceRasterTest, NearestFreeSkipsClosedCellsAsItSkipsMarkedOnes)
{
  const FreeSpaceRaster raster = unitWindow();
  std::vector<std::size_t> closed = {cellAt(5, 5), cellAt(4, 4), cellAt(4, 5), cellAt(4, 6), cellAt(5, 4)};
  std::sort(closed.begin(), closed.end());
  FreeSpaceRaster marked = raster;
  marked.mark(closed, FreeSpaceRaster::kMovable);
  const Point point(0.55, 0.55);
  const auto expected = marked.nearestFree(point, FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable, 2);
  ASSERT_TRUE(expected.has_value());
  EXPECT_EQ(*expected, cellAt(5, 6));
  EXPECT_EQ(raster.nearestFree(point, FreeSpaceRaster::kObstacle, 2, closed), expected);
  EXPECT_EQ(raster.nearestFree(point, FreeSpaceRaster::kObstacle, 2), cellAt(5, 5));
}

}  // namespace
}  // namespace ifar::interaction
