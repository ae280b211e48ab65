#pragma once
// Cost-to-go to the target over a small grid around the vehicle (a navigation function): the follower
// scores arcs by how much they lower it, so an obstacle across the straight line is driven around
// instead of trapping the vehicle in front of it (a plain distance-to-target score has that local minimum).
// Cells near obstacles cost more to cross, so the cost-to-go leads down the middle of a door or a tunnel
// instead of along the inflated wall a visibility-graph path hugs.

#include <limits>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"

namespace ifar::executive {

struct NavigationFieldShape {
  double half_size_m = 6.0;  ///< the window is a square of this half-size around its centre
  double cell_size_m = 0.2;  ///< cell width
  double blocked_m = 0.35;   ///< cells whose centre is closer than this to an obstacle point are blocked
  double comfort_m = 0.85;   ///< crossing a cell closer than this to an obstacle point costs extra
  double proximity_weight =
      0.0;  ///< at blocked_m a cell costs (1 + weight) x its length, falling to 1 at comfort_m
  /// Unblock the cells around the target (the goal may stand beside an object and must stay reachable);
  /// otherwise a target in blocked cells is reached at the free cells nearest it.
  bool open_around_target = true;
};

class NavigationField {
 public:
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();

  /// The window of `shape` around `centre`. A target outside the window is reached through the window's
  /// border, whose cells start with their straight-line distance to it.
  NavigationField(common::Span<const geometry::Point> obstacles, const geometry::Point& centre,
                  const geometry::Point& target, const NavigationFieldShape& shape);

  /// Cost-to-go in metres (proximity cost included) at `point`, interpolated between cell centres;
  /// kUnreachable in blocked or unreachable cells and outside the window.
  double value(const geometry::Point& point) const;

  /// The direction (radians, world frame) in which the cost-to-go falls fastest from `point`: the lowest
  /// of `directions` samples on a circle of `radius_m` around it. Empty when no sample has a finite value.
  std::optional<double> descentDirection(const geometry::Point& point, double radius_m,
                                         int directions = 32) const;

 private:
  double cellValue(int column, int row) const;

  geometry::Point origin_;
  double cell_size_;
  int cells_per_side_;
  std::vector<double> cost_;
};

}  // namespace ifar::executive
