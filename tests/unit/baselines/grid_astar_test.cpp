#include "bench/baselines/grid_astar.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace ifar::baselines {
namespace {

using grid_map::Cell;
using grid_map::CellIndex;
using grid_map::GridMap;

constexpr double kSqrt2 = 1.4142135623730951;

GridMap openMap(int width, int height, double resolution = 1.0)
{
  return GridMap(width, height, resolution, geometry::Point::Zero(), Cell::Free);
}

TEST(GridAStar, OpenGridGivesOctileLength)
{
  GridAStar search(openMap(5, 5));
  GridSearchStats stats;
  const BaselineResult result = search.findPath(CellIndex{0, 0}, CellIndex{4, 2}, &stats);
  ASSERT_EQ(result.status, BaselineStatus::Solved);
  EXPECT_NEAR(result.length, 2.0 * kSqrt2 + 2.0, 1e-12);
  EXPECT_EQ(stats.path_cells, 5u);
}

TEST(GridAStar, GoesAroundWallWithoutCuttingCorners)
{
  // Wall in column 2 from y = 0 to y = 3; the only gap is at y = 4.
  GridMap map = openMap(5, 5);
  for (int y = 0; y <= 3; ++y) {
    map.set(2, y, Cell::Blocked);
  }
  GridAStar search(map);
  const BaselineResult result = search.findPath(CellIndex{0, 0}, CellIndex{4, 0});
  ASSERT_EQ(result.status, BaselineStatus::Solved);
  // (0,0) -> (1,4): 3 + sqrt2; through the gap (1,4) -> (3,4): 2; (3,4) -> (4,0): 3 + sqrt2.
  EXPECT_NEAR(result.length, 8.0 + 2.0 * kSqrt2, 1e-12);
  for (const auto& point : result.path) {
    EXPECT_FALSE(
        search.blocked(static_cast<int>(std::floor(point.x())), static_cast<int>(std::floor(point.y()))));
  }
}

TEST(GridAStar, RefusesDiagonalSqueeze)
{
  // Two blocked cells touching only at a corner: the diagonal move between the free ones is refused.
  GridMap map = openMap(2, 2);
  map.set(1, 0, Cell::Blocked);
  map.set(0, 1, Cell::Blocked);
  GridAStar search(map);
  const BaselineResult result = search.findPath(CellIndex{0, 0}, CellIndex{1, 1});
  EXPECT_EQ(result.status, BaselineStatus::NoPath);
  EXPECT_TRUE(std::isnan(result.length));
}

TEST(GridAStar, ScalesByResolutionAndAddsEndPieces)
{
  GridAStar search(openMap(10, 4, 0.15));
  // Cell centres of (0, 1) and (7, 1): 7 straight steps.
  const BaselineResult cells = search.findPath(CellIndex{0, 1}, CellIndex{7, 1});
  ASSERT_EQ(cells.status, BaselineStatus::Solved);
  EXPECT_NEAR(cells.length, 7 * 0.15, 1e-12);
  // World points on the left edge of cell (0, 1) and a quarter cell right of the centre of (7, 1).
  const BaselineResult world =
      search.findPath(geometry::Point(0.0, 1.5 * 0.15), geometry::Point(7.75 * 0.15, 1.5 * 0.15));
  ASSERT_EQ(world.status, BaselineStatus::Solved);
  EXPECT_NEAR(world.length, 7.75 * 0.15, 1e-12);
}

TEST(GridAStar, ReportsBlockedEndsAndDisconnectedGoals)
{
  GridMap map = openMap(5, 3);
  for (int y = 0; y < 3; ++y) {
    map.set(2, y, Cell::Blocked);
  }
  GridAStar search(map);
  EXPECT_EQ(search.findPath(CellIndex{2, 1}, CellIndex{0, 0}).status, BaselineStatus::InvalidStart);
  EXPECT_EQ(search.findPath(CellIndex{0, 0}, CellIndex{9, 0}).status, BaselineStatus::InvalidGoal);
  const BaselineResult split = search.findPath(CellIndex{0, 0}, CellIndex{4, 2});
  EXPECT_EQ(split.status, BaselineStatus::NoPath);
  EXPECT_FALSE(split.reason.empty());
  // The same object answers again correctly after a failed search.
  const BaselineResult again = search.findPath(CellIndex{0, 0}, CellIndex{1, 2});
  ASSERT_EQ(again.status, BaselineStatus::Solved);
  EXPECT_NEAR(again.length, 1.0 + kSqrt2, 1e-12);
}

TEST(GridAStar, UnknownCellsFollowThePolicy)
{
  GridMap map = openMap(3, 1);
  map.set(1, 0, Cell::Unknown);
  GridAStar blocked_unknown(map, grid_map::UnknownPolicy::AsBlocked);
  EXPECT_EQ(blocked_unknown.findPath(CellIndex{0, 0}, CellIndex{2, 0}).status, BaselineStatus::NoPath);
  GridAStar free_unknown(map, grid_map::UnknownPolicy::AsFree);
  const BaselineResult result = free_unknown.findPath(CellIndex{0, 0}, CellIndex{2, 0});
  ASSERT_EQ(result.status, BaselineStatus::Solved);
  EXPECT_NEAR(result.length, 2.0, 1e-12);
}

}  // namespace
}  // namespace ifar::baselines
