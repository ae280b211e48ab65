#include "planner/perception/grazing_gap_fill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"

namespace ifar::perception {
namespace {

using geometry::kPi;
using geometry::Point;

constexpr double kDegree = kPi / 180.0;

struct Segment {
  Point from;
  Point to;
};

// A planar lidar at the origin: one ray every `step_deg`, each returning its nearest hit on `walls`.
std::vector<Point> scan(const std::vector<Segment>& walls, double step_deg = 0.2)
{
  std::vector<Point> returns;
  const auto rays = static_cast<int>(std::floor((360.0 - 0.05) / step_deg));
  for (int ray = 0; ray <= rays; ++ray) {
    const double azimuth = (0.05 + ray * step_deg) * kDegree;
    const Point direction(std::cos(azimuth), std::sin(azimuth));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Segment& wall : walls) {
      const Point along = wall.to - wall.from;
      const double denominator = geometry::cross(direction, along);
      if (std::abs(denominator) < 1e-12) {
        continue;
      }
      const double range = geometry::cross(wall.from, along) / denominator;
      const double fraction = geometry::cross(wall.from, direction) / denominator;
      if (range > 0.0 && fraction >= 0.0 && fraction <= 1.0) {
        nearest = std::min(nearest, range);
      }
    }
    if (nearest < 100.0) {
      returns.push_back(direction * nearest);
    }
  }
  return returns;
}

GrazingGapSettings settings()
{
  GrazingGapSettings gaps;
  gaps.azimuth_step_rad = 0.2 * kDegree;
  gaps.min_incidence_rad = 3.0 * kDegree;
  gaps.spacing_m = 0.075;
  return gaps;
}

// The widest step between neighbouring points on the line x = `x` with y in [y_from, y_to].
double widestGap(const std::vector<Point>& points, double x, double y_from, double y_to)
{
  std::vector<double> ys;
  for (const Point& point : points) {
    if (std::abs(point.x() - x) < 1e-6 && point.y() >= y_from && point.y() <= y_to) {
      ys.push_back(point.y());
    }
  }
  ys.push_back(y_from);
  ys.push_back(y_to);
  std::sort(ys.begin(), ys.end());
  double widest = 0.0;
  for (std::size_t index = 1; index < ys.size(); ++index) {
    widest = std::max(widest, ys[index] - ys[index - 1]);
  }
  return widest;
}

TEST(GrazingGapFill, AFarCorridorWallIsJoinedWhereItsReturnsLieMetresApart)
{
  const std::vector<Point> returns = scan({{Point(2.0, 1.0), Point(2.0, 60.0)}});
  // Without filling, the returns 30 m along the wall, seen at 3.8 degrees, lie metres apart.
  EXPECT_GT(widestGap(returns, 2.0, 25.0, 30.0), 1.0);
  std::vector<Point> filled = fillGrazingGaps(returns, {}, Point::Zero(), settings());
  filled.insert(filled.end(), returns.begin(), returns.end());
  EXPECT_LE(widestGap(filled, 2.0, 1.5, 30.0), 0.075 + 1e-9);
  // Flatter than 3 degrees (beyond 2 / tan(3 degrees) = 38 m) the wall is left as the rays saw it.
  EXPECT_GT(widestGap(filled, 2.0, 45.0, 55.0), 1.0);
}

TEST(GrazingGapFill, ADoorwayARayWentThroughStaysOpen)
{
  // A wall 5 m ahead with a 1 m doorway, and a back wall 15 m ahead seen through it.
  const std::vector<Segment> walls = {{Point(5.0, -10.0), Point(5.0, 1.0)},
                                      {Point(5.0, 2.0), Point(5.0, 10.0)},
                                      {Point(15.0, -20.0), Point(15.0, 20.0)}};
  const std::vector<Point> returns = scan(walls);
  const std::vector<Point> filled = fillGrazingGaps(returns, {}, Point::Zero(), settings());
  EXPECT_FALSE(filled.empty());  // the walls themselves are sampled every 0.2 degrees: small joins
  for (const Point& point : filled) {
    EXPECT_FALSE(point.x() > 4.9 && point.x() < 14.9 && point.y() > 1.0 && point.y() < 2.0)
        << "fill point in the doorway at " << point.transpose();
  }
}

TEST(GrazingGapFill, AnObjectIsNotJoinedToTheWallBehindIt)
{
  // A box 1 m wide at 5 m and the wall 2 m behind it: neighbouring returns jump 2 m at the box's edges.
  const std::vector<Point> wall = scan({{Point(7.0, -10.0), Point(7.0, 10.0)}});
  const std::vector<Point> box = scan({{Point(5.0, -0.5), Point(5.0, 0.5)}});
  std::vector<Point> background;
  for (const Point& point : wall) {
    if (std::abs(point.y() / point.x()) > 0.5 / 5.0 + 1e-9) {
      background.push_back(point);  // the box shadows the wall's middle
    }
  }
  for (const bool box_is_movable : {true, false}) {
    std::vector<Point> scene = background;
    if (!box_is_movable) {
      scene.insert(scene.end(), box.begin(), box.end());
    }
    const std::vector<Point> filled =
        fillGrazingGaps(scene, box_is_movable ? box : std::vector<Point>{}, Point::Zero(), settings());
    for (const Point& point : filled) {
      EXPECT_FALSE(point.x() > 5.1 && point.x() < 6.9)
          << "fill point in the box's shadow at " << point.transpose();
    }
  }
}

TEST(GrazingGapFill, MovableReturnsJoinNothing)
{
  const std::vector<Point> returns = scan({{Point(2.0, 1.0), Point(2.0, 60.0)}});
  EXPECT_TRUE(fillGrazingGaps({}, returns, Point::Zero(), settings()).empty());
}

TEST(GrazingGapFill, ASensorAwayFromTheOriginJoinsTheSameWall)
{
  const std::vector<Point> returns = scan({{Point(2.0, 1.0), Point(2.0, 60.0)}});
  const Point offset(-30.0, 12.5);
  std::vector<Point> moved;
  moved.reserve(returns.size());
  for (const Point& point : returns) {
    moved.push_back(point + offset);
  }
  const std::vector<Point> at_origin = fillGrazingGaps(returns, {}, Point::Zero(), settings());
  const std::vector<Point> away = fillGrazingGaps(moved, {}, offset, settings());
  ASSERT_EQ(away.size(), at_origin.size());
  for (std::size_t index = 0; index < away.size(); ++index) {
    EXPECT_NEAR((away[index] - offset - at_origin[index]).norm(), 0.0, 1e-9);
  }
}

TEST(GrazingGapFill, OffOrWithANonFiniteSensorFillsNothing)
{
  const std::vector<Point> returns = scan({{Point(2.0, 1.0), Point(2.0, 60.0)}});
  GrazingGapSettings off = settings();
  off.azimuth_step_rad = 0.0;
  EXPECT_TRUE(fillGrazingGaps(returns, {}, Point::Zero(), off).empty());
  EXPECT_TRUE(fillGrazingGaps(returns, {}, Point(std::nan(""), 0.0), settings()).empty());
}

}  // namespace
}  // namespace ifar::perception
