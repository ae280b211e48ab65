#pragma once
// Cost-to-go to the target over a small grid around the vehicle (a navigation function): the follower
// scores arcs by how much they lower it, so an obstacle across the straight line is driven around
// instead of trapping the vehicle in front of it (a plain distance-to-target score has that local minimum).

#include <limits>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"

namespace ifar::executive {

class NavigationField {
 public:
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();

  /// A square window of half-size `half_size_m` around `centre`, cells `cell_size_m` wide. Cells within
  /// `inflation_m` of an obstacle point are blocked, except around the target (a target beside an
  /// object must stay reachable). A target outside the window is reached through the window's border,
  /// whose cells start with their straight-line distance to it.
  NavigationField(common::Span<const geometry::Point> obstacles, const geometry::Point& centre,
                  double half_size_m, double cell_size_m, double inflation_m, const geometry::Point& target);

  /// Cost-to-go in metres at `point`, interpolated between cell centres; kUnreachable in blocked or
  /// unreachable cells and outside the window.
  double value(const geometry::Point& point) const;

 private:
  double cellValue(int column, int row) const;

  geometry::Point origin_;
  double cell_size_;
  int cells_per_side_;
  std::vector<double> cost_;
};

}  // namespace ifar::executive
