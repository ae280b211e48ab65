#include "executive/follower/navigation_field.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;

/// Points every 5 cm from `from` to `to`.
void addWall(std::vector<Point>& points, const Point& from, const Point& to)
{
  const int count = static_cast<int>(std::ceil((to - from).norm() / 0.05));
  for (int index = 0; index <= count; ++index) {
    points.push_back(from + (to - from) * (static_cast<double>(index) / count));
  }
}

common::Span<const Point> spanOf(const std::vector<Point>& points)
{
  return common::Span<const Point>(points.data(), points.size());
}

/// The vehicle's numbers: 0.35 m half width, costs up to 0.5 m beyond it.
NavigationFieldShape vehicleShape(double proximity_weight)
{
  NavigationFieldShape shape;
  shape.half_size_m = 6.0;
  shape.cell_size_m = 0.2;
  shape.blocked_m = 0.35;
  shape.comfort_m = 0.85;
  shape.proximity_weight = proximity_weight;
  return shape;
}

double degreesBetween(double a, double b)
{
  return std::abs(wrapToPi(a - b)) * 180.0 / kPi;
}

// A 1.0 m door in a long wall: the 0.7 m vehicle fits with 0.15 m a side. Blocking everything within
// half width + that clearance (as the field did) closes it; blocking the half width and charging for
// the rest leads through its middle.
TEST(NavigationField, ADoorOnlyClearanceWiderThanTheVehicleLeadsThroughItsMiddle)
{
  std::vector<Point> wall;
  addWall(wall, Point(-6.0, 0.0), Point(-0.5, 0.0));
  addWall(wall, Point(0.5, 0.0), Point(6.0, 0.0));
  const Point target(0.0, 3.0);
  const Point below(0.6, -1.5);

  const NavigationField field(spanOf(wall), Point(0.0, 0.0), target, vehicleShape(3.0));
  ASSERT_TRUE(std::isfinite(field.value(below)));
  EXPECT_LT(field.value(below), 8.0);
  const std::optional<double> descent = field.descentDirection(below, 0.5);
  ASSERT_TRUE(descent);
  EXPECT_GT(*descent, 0.5 * kPi);  // up and to the left, toward the door's middle
  EXPECT_LT(*descent, 0.85 * kPi);

  NavigationFieldShape closed = vehicleShape(3.0);
  closed.blocked_m = 0.5;
  const NavigationField closed_field(spanOf(wall), Point(0.0, 0.0), target, closed);
  EXPECT_FALSE(std::isfinite(closed_field.value(below)));
}

// Along a wall toward a target far ahead: with the proximity cost the way leads off the wall, without
// it straight along it.
TEST(NavigationField, ProximityCostLeadsOffTheWall)
{
  std::vector<Point> wall;
  addWall(wall, Point(-8.0, 0.0), Point(8.0, 0.0));
  const Point target(20.0, 0.6);
  const Point beside(0.0, 0.6);

  const NavigationField charged(spanOf(wall), beside, target, vehicleShape(3.0));
  const std::optional<double> off = charged.descentDirection(beside, 0.5);
  ASSERT_TRUE(off);
  EXPECT_GT(*off, 10.0 * kPi / 180.0);
  EXPECT_LT(*off, 0.5 * kPi);

  const NavigationField plain(spanOf(wall), beside, target, vehicleShape(0.0));
  const std::optional<double> along = plain.descentDirection(beside, 0.5);
  ASSERT_TRUE(along);
  EXPECT_LT(degreesBetween(*along, 0.0), 10.0);
}

// A waypoint on the inflated outline (where visibility-graph paths run): reached from the free cells
// next to it, or, at the goal, through cells opened around it.
TEST(NavigationField, ATargetInsideTheBlockedCellsIsReachedBesideIt)
{
  std::vector<Point> wall;
  addWall(wall, Point(-6.0, 0.0), Point(6.0, 0.0));
  const Point target(3.0, 0.2);

  NavigationFieldShape beside = vehicleShape(3.0);
  beside.open_around_target = false;
  const NavigationField waypoint(spanOf(wall), Point(0.0, 1.0), target, beside);
  EXPECT_FALSE(std::isfinite(waypoint.value(target)));
  EXPECT_LT(waypoint.value(Point(3.0, 0.6)), 0.6);
  EXPECT_TRUE(std::isfinite(waypoint.value(Point(0.0, 1.0))));

  const NavigationField goal(spanOf(wall), Point(0.0, 1.0), target, vehicleShape(3.0));
  EXPECT_LT(goal.value(target), 0.2);
}

TEST(NavigationField, NoFiniteSampleGivesNoDirection)
{
  const std::vector<Point> none;
  const NavigationField field(spanOf(none), Point(0.0, 0.0), Point(1.0, 0.0), vehicleShape(3.0));
  EXPECT_FALSE(field.descentDirection(Point(100.0, 100.0), 0.5));
  const std::optional<double> toward = field.descentDirection(Point(0.0, 0.0), 0.5);
  ASSERT_TRUE(toward);
  EXPECT_LT(degreesBetween(*toward, 0.0), 12.0);
}

}  // namespace
}  // namespace ifar::executive
