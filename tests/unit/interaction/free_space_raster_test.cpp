#include "planner/interaction/free_space_raster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
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

}  // namespace
}  // namespace ifar::interaction
