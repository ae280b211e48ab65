#include "planner/perception/background_memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace ifar::perception {
namespace {

using geometry::Point;

common::Span<const Point> spanOf(const std::vector<Point>& points)
{
  return common::Span<const Point>(points.data(), points.size());
}

TEST(BackgroundMemory, RemembersOneCellPerPointAtItsCentre)
{
  BackgroundMemory memory(0.15);
  const std::vector<Point> points{{1.00, 2.00}, {1.01, 2.02}, {-0.01, -0.01}};
  memory.remember(spanOf(points));
  EXPECT_EQ(memory.size(), 2U);  // the first two share a cell
  std::vector<Point> cells = memory.cellsWithin(Point(-10.0, -10.0), Point(10.0, 10.0));
  ASSERT_EQ(cells.size(), 2U);
  std::sort(cells.begin(), cells.end(), [](const Point& a, const Point& b) { return a.x() < b.x(); });
  EXPECT_NEAR(cells[0].x(), -0.075, 1e-12);  // cell -1: [-0.15, 0)
  EXPECT_NEAR(cells[0].y(), -0.075, 1e-12);
  EXPECT_NEAR(cells[1].x(), 6 * 0.15 + 0.075, 1e-12);   // 1.00 lies in cell 6: [0.90, 1.05)
  EXPECT_NEAR(cells[1].y(), 13 * 0.15 + 0.075, 1e-12);  // 2.00 lies in cell 13: [1.95, 2.10)
}

TEST(BackgroundMemory, GivesOnlyTheCellsInsideTheWindow)
{
  BackgroundMemory memory(0.5);
  std::vector<Point> wall;
  wall.reserve(40);
  for (int step = 0; step < 40; ++step) {
    wall.emplace_back(0.1 + 0.5 * step, 3.1);
  }
  memory.remember(spanOf(wall));
  EXPECT_EQ(memory.size(), 40U);
  const std::vector<Point> inside = memory.cellsWithin(Point(5.0, 0.0), Point(10.0, 5.0));
  EXPECT_EQ(inside.size(), 10U);
  for (const Point& cell : inside) {
    EXPECT_GE(cell.x(), 5.0);
    EXPECT_LT(cell.x(), 10.0);
    EXPECT_DOUBLE_EQ(cell.y(), 3.25);
  }
}

TEST(BackgroundMemory, WindowsAcrossTilesAndNegativeCellsGiveWhatABruteForceGives)
{
  // Cells are stored in tiles: windows that cut tiles, cells on either side of zero and cells far from
  // the origin must come back exactly as a scan of every remembered cell would give them.
  constexpr double kCell = 0.15;
  BackgroundMemory memory(kCell);
  std::vector<Point> points;
  std::uint64_t state = 12345;
  const auto uniform = [&state](double low, double high) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return low + (high - low) * static_cast<double>(state >> 11U) / 9007199254740992.0;
  };
  for (int index = 0; index < 3000; ++index) {
    points.emplace_back(uniform(-20.0, 20.0), uniform(-20.0, 20.0));
  }
  points.emplace_back(-100000.0, 250000.0);
  memory.remember(spanOf(points));
  std::vector<std::pair<std::int64_t, std::int64_t>> distinct;
  for (const Point& point : points) {
    distinct.emplace_back(static_cast<std::int64_t>(std::floor(point.x() / kCell)),
                          static_cast<std::int64_t>(std::floor(point.y() / kCell)));
  }
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  ASSERT_EQ(memory.size(), distinct.size());
  const auto key = [](const Point& centre) {
    return std::make_pair(static_cast<std::int64_t>(std::floor(centre.x() / kCell)),
                          static_cast<std::int64_t>(std::floor(centre.y() / kCell)));
  };
  for (int window = 0; window < 50; ++window) {
    const Point minimum(uniform(-25.0, 15.0), uniform(-25.0, 15.0));
    const Point maximum = minimum + Point(uniform(0.0, 12.0), uniform(0.0, 12.0));
    std::vector<std::pair<std::int64_t, std::int64_t>> expected;
    for (const auto& [column, row] : distinct) {
      const Point centre((column + 0.5) * kCell, (row + 0.5) * kCell);
      if (centre.x() >= minimum.x() && centre.y() >= minimum.y() && centre.x() < maximum.x() &&
          centre.y() < maximum.y()) {
        expected.emplace_back(column, row);
      }
    }
    std::vector<std::pair<std::int64_t, std::int64_t>> got;
    for (const Point& centre : memory.cellsWithin(minimum, maximum)) {
      got.push_back(key(centre));
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, expected) << "window " << window;
  }
  const std::vector<Point> far = memory.cellsWithin(Point(-100001.0, 249999.0), Point(-99999.0, 250001.0));
  ASSERT_EQ(far.size(), 1U);
  EXPECT_EQ(memory.votesAt(Point(-100000.0, 250000.0)), 1);
  EXPECT_EQ(memory.cellsWithin(Point(-1e300, -1e300), Point(1e300, 1e300)).size(), distinct.size());
  EXPECT_EQ(memory.forgetMarkedBefore(memory.markCount() + 1), distinct.size());
  EXPECT_EQ(memory.size(), 0U);
  EXPECT_TRUE(memory.cellsWithin(Point(-30.0, -30.0), Point(30.0, 30.0)).empty());
}

TEST(BackgroundMemory, SkipsNonFiniteAndFarPointsAndUnusableCellSizes)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  const std::vector<Point> points{{nan, 1.0}, {1.0, infinity}, {1e300, 0.0}, {2.0, 2.0}};
  BackgroundMemory memory(0.15);
  memory.remember(spanOf(points));
  EXPECT_EQ(memory.size(), 1U);

  BackgroundMemory unusable(0.0);
  unusable.remember(spanOf(points));
  EXPECT_EQ(unusable.size(), 0U);
}

TEST(BackgroundMemory, AnInflatedOutlineLeavesTheObjectsOwnCells)
{
  // A 1.2 m x 0.6 m box centred at (5, 5), its outline inflated by 0.35 m (square corners are enough):
  // the cells remembered are the box's own (within half a cell of its sides), not the inflation band.
  const geometry::Polygon inflated{{4.05, 4.35}, {5.95, 4.35}, {5.95, 5.65}, {4.05, 5.65}};
  BackgroundMemory memory(0.15);
  const std::size_t cells = memory.rememberInflatedOutline(inflated, 0.35);
  EXPECT_EQ(cells, memory.size());
  const std::vector<Point> remembered = memory.cellsWithin(Point(0.0, 0.0), Point(10.0, 10.0));
  ASSERT_FALSE(remembered.empty());
  double min_x = 10.0;
  double max_x = 0.0;
  for (const Point& cell : remembered) {
    EXPECT_GE(cell.x(), 4.4 - 0.075 - 1e-9);
    EXPECT_LE(cell.x(), 5.6 + 0.075 + 1e-9);
    EXPECT_GE(cell.y(), 4.7 - 0.075 - 1e-9);
    EXPECT_LE(cell.y(), 5.3 + 0.075 + 1e-9);
    min_x = std::min(min_x, cell.x());
    max_x = std::max(max_x, cell.x());
  }
  EXPECT_LT(min_x, 4.5);  // and it reaches the box's sides
  EXPECT_GT(max_x, 5.5);

  EXPECT_EQ(memory.rememberInflatedOutline(geometry::Polygon{{0.0, 0.0}, {1.0, 0.0}}, 0.35), 0U);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(memory.rememberInflatedOutline(geometry::Polygon{{0.0, 0.0}, {1.0, nan}, {1.0, 1.0}}, 0.35), 0U);
}

TEST(BackgroundMemory, AnOutlineMarksTheCellsItsEdgesCrossAndNoneInside)
{
  // A 3 m x 1.5 m wall block from (0.1, 0.1) in 0.5 m cells: its edges cross the cells of rows 0 and
  // 3 (x 0.1 .. 3.1: columns 0 .. 6) and of columns 0 and 6 (y 0.1 .. 1.6: rows 0 .. 3).
  const geometry::Polygon block{{0.1, 0.1}, {3.1, 0.1}, {3.1, 1.6}, {0.1, 1.6}};
  BackgroundMemory memory(0.5);
  EXPECT_EQ(memory.rememberOutline(block), 7U + 7U + 2U + 2U);
  for (const Point& cell : memory.cellsWithin(Point(-5.0, -5.0), Point(5.0, 5.0))) {
    const bool on_a_row = std::abs(cell.y() - 0.25) < 1e-9 || std::abs(cell.y() - 1.75) < 1e-9;
    const bool on_a_column = std::abs(cell.x() - 0.25) < 1e-9 || std::abs(cell.x() - 3.25) < 1e-9;
    EXPECT_TRUE(on_a_row || on_a_column) << cell.transpose();
  }
  EXPECT_EQ(memory.rememberOutline(block), 0U) << "nothing new the second time";

  // A long diagonal edge leaves no gap: no point of it is a cell or more from a marked cell's centre.
  BackgroundMemory diagonal(0.15);
  diagonal.rememberOutline(geometry::Polygon{{0.0, 0.0}, {30.0, 10.0}});
  EXPECT_GE(diagonal.size(), 200U);  // at least one cell in each of the 200 columns it spans
  for (int step = 0; step <= 10000; ++step) {
    const double along = 1e-4 * step;
    const Point point(30.0 * along, 10.0 * along);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Point& cell : diagonal.cellsWithin(point - Point(0.3, 0.3), point + Point(0.3, 0.3))) {
      nearest = std::min(nearest, (cell - point).norm());
    }
    ASSERT_LT(nearest, 0.15) << point.transpose();
  }

  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(memory.rememberOutline(geometry::Polygon{{10.0, 10.0}, {11.0, nan}, {11.0, 11.0}}), 0U);
  EXPECT_EQ(memory.rememberOutline(geometry::Polygon{}), 0U);
}

/// A level scan from a sensor 0.8 m above the ground at the origin: one return every 0.1 degrees, each
/// `range_m` away at the sensor's height (a wall all round).
FreeSpaceView levelScan(double range_m)
{
  std::vector<WorldPoint> points;
  points.reserve(3600);
  for (int step = 0; step < 3600; ++step) {
    const double azimuth = step * 0.1 * 3.14159265358979323846 / 180.0;
    WorldPoint point;
    point.sensor_world = Eigen::Vector3d(0.0, 0.0, 0.8);
    point.position_world = Eigen::Vector3d(range_m * std::cos(azimuth), range_m * std::sin(azimuth), 0.8);
    point.height_above_ground_m = 0.8;
    point.range_m = range_m;
    points.push_back(point);
  }
  return FreeSpaceView(common::Span<const WorldPoint>(points.data(), points.size()), Point(0.0, 0.0),
                       FreeSpaceSettings{});
}

// A cell seen in three scans goes after three scans see through it; a wall the rays end at stays; so does
// an obstacle lower than every ray that passed over it; beyond the range nothing is checked.
TEST(BackgroundMemory, ScansThatSeeThroughACellTakeItsVotesAway)
{
  BackgroundMemory memory(0.15, 5);
  const std::vector<Point> stray{{5.0, 0.05}};
  const std::vector<Point> wall{{10.05, 0.05}};
  const std::vector<Point> low{{0.05, 6.0}};
  const std::vector<float> low_height{0.3F};
  const std::vector<Point> far{{0.05, -30.0}};
  for (int scan = 0; scan < 3; ++scan) {
    memory.remember(spanOf(stray));
    memory.remember(spanOf(wall));
    memory.remember(spanOf(low), common::Span<const float>(low_height.data(), low_height.size()));
  }
  memory.remember(spanOf(far));
  EXPECT_EQ(memory.votesAt(stray.front()), 3);
  const FreeSpaceView view = levelScan(10.0);
  for (int scan = 1; scan <= 3; ++scan) {
    const ForgetStats stats = memory.forgetSeenThrough(view, 20.0);
    EXPECT_EQ(stats.checked, 3U);  // the far cell is out of range
    EXPECT_EQ(memory.votesAt(stray.front()), 3 - scan);
    EXPECT_EQ(stats.forgotten, scan == 3 ? 1U : 0U);
  }
  EXPECT_EQ(memory.votesAt(wall.front()), 3) << "the rays end at the wall";
  EXPECT_EQ(memory.votesAt(low.front()), 3) << "the rays pass over it at 0.8 m";
  EXPECT_EQ(memory.votesAt(far.front()), 1);
  EXPECT_EQ(memory.size(), 3U);
  // One scan gives a cell one vote at most, however many of its returns fall in it.
  const std::vector<Point> twice{{2.0, 2.0}, {2.01, 2.01}};
  memory.remember(spanOf(twice));
  EXPECT_EQ(memory.votesAt(twice.front()), 1);
}

// A scan without returns sees through nothing; a cell holding the sensor is never seen through.
TEST(BackgroundMemory, NoRaysNoForgetting)
{
  BackgroundMemory memory(0.15, 5);
  const std::vector<Point> cells{{5.0, 0.05}, {0.01, 0.01}};
  memory.remember(spanOf(cells));
  EXPECT_EQ(memory.forgetSeenThrough(FreeSpaceView{}, 20.0).seen_through, 0U);
  const ForgetStats stats = memory.forgetSeenThrough(levelScan(10.0), 20.0);
  EXPECT_EQ(stats.seen_through, 1U);
  EXPECT_EQ(memory.votesAt(cells[1]), 1);
}

// A cell the rays passed or ended at is reached; one behind where they ended is not, nor one where no
// ray went, nor the sensor's own.
TEST(FreeSpaceView, ReachesTheCellsTheRaysGotTo)
{
  const FreeSpaceView view = levelScan(10.0);
  EXPECT_TRUE(view.reaches(Point(5.0, 0.05), 0.15));    // passed
  EXPECT_TRUE(view.reaches(Point(10.05, 0.05), 0.15));  // ended in it
  EXPECT_FALSE(view.reaches(Point(10.5, 0.05), 0.15));  // behind the wall
  EXPECT_FALSE(view.reaches(Point(0.01, 0.01), 0.15));  // holds the sensor
  EXPECT_FALSE(FreeSpaceView{}.reaches(Point(5.0, 0.05), 0.15));
}

TEST(BackgroundMemory, ForgettingWhatWasMarkedBeforeAScanKeepsThatScanAndUnpushableObjects)
{
  BackgroundMemory memory(1.0, 5);
  const std::vector<geometry::Point> old_wall = {geometry::Point(0.5, 0.5), geometry::Point(1.5, 0.5)};
  memory.remember(spanOf(old_wall));
  const geometry::Polygon unpushable = {geometry::Point(10, 10), geometry::Point(14, 10),
                                        geometry::Point(14, 14), geometry::Point(10, 14)};
  const std::size_t object_cells = memory.rememberInflatedOutline(unpushable, 1.0);
  ASSERT_GT(object_cells, 0U);
  const std::uint32_t latest_scan = memory.markCount() + 1;
  const std::vector<geometry::Point> seen_now = {geometry::Point(1.5, 0.5), geometry::Point(5.5, 5.5)};
  memory.remember(spanOf(seen_now));
  EXPECT_EQ(memory.markCount(), latest_scan);
  EXPECT_EQ(memory.size(), 3U + object_cells);

  EXPECT_EQ(memory.forgetMarkedBefore(latest_scan), 1U);  // only (0.5, 0.5): (1.5, 0.5) was seen again
  EXPECT_EQ(memory.votesAt(geometry::Point(0.5, 0.5)), 0);
  EXPECT_EQ(memory.votesAt(geometry::Point(1.5, 0.5)), 2);
  EXPECT_EQ(memory.votesAt(geometry::Point(5.5, 5.5)), 1);
  EXPECT_EQ(memory.votesAt(geometry::Point(12.5, 12.5)), 5);
  EXPECT_EQ(memory.size(), 2U + object_cells);
}

}  // namespace
}  // namespace ifar::perception
