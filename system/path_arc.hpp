#pragma once
// A planned path as a curve measured along its length: where a point projects onto it (the nearest
// point, optionally only among the stretch between two arc lengths) and how far that is from the start.
// Following progress is the change of the projection's arc length; limiting the search to a stretch
// around the last projection keeps it from jumping across a bend or to a later part of a path that
// comes back near the vehicle.

#include <cstddef>
#include <limits>
#include <vector>

#include "common/geometry/point.hpp"

namespace ifar::runner {

class PathArc {
 public:
  /// `polyline`: the path's points, start first (empty: a path of length 0 at the origin).
  explicit PathArc(std::vector<geometry::Point> polyline);

  struct Foot {
    std::size_t segment = 0;  // the foot lies on polyline()[segment] .. polyline()[segment + 1]
    geometry::Point point = geometry::Point::Zero();
    double arc = 0.0;       // the path's length from its start to the foot
    double distance = 0.0;  // from the projected point to the foot
  };
  /// The nearest point of the path to `point` among those with arc length in [arc_min, arc_max] (the
  /// first such on ties).
  Foot nearest(const geometry::Point& point, double arc_min = 0.0,
               double arc_max = std::numeric_limits<double>::infinity()) const;

  double length() const { return arc_.empty() ? 0.0 : arc_.back(); }
  const std::vector<geometry::Point>& polyline() const { return polyline_; }

  /// What is left of the path for a vehicle at `point`: the point, its foot, and the path on from there.
  std::vector<geometry::Point> remainderFrom(const geometry::Point& point) const;

 private:
  std::vector<geometry::Point> polyline_;
  std::vector<double> arc_;  // per point: the path's length from the start to it
};

}  // namespace ifar::runner
