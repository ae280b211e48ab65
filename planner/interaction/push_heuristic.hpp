#pragma once
// The push search's cost-to-go estimate (paper VI.C): the width of the heuristic polygon, the object's
// footprint clipped to the passage window, found by rotating calipers, at the cheapest push's cost per
// metre. Pushing the object that far, at least, is what clearing the passage takes.

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"
#include "planner/interaction/push_goal_region.hpp"

namespace ifar::interaction {

class PushHeuristic {
 public:
  /// `footprint` is body frame; the cheapest push takes `smallest_force_n`, and the search's cost counts
  /// force x distance / `reference_force_n`.
  PushHeuristic(const geometry::Polygon& footprint, double smallest_force_n, double reference_force_n)
      : footprint_(footprint), cost_per_metre_(smallest_force_n / reference_force_n)
  {
  }

  /// Estimated cost (equivalent metres) from the object at `pose` to `region`; 0 once it is out of the
  /// passage window.
  double costToGo(const geometry::Pose2& pose, const PushGoalRegion& region) const;

 private:
  geometry::Polygon footprint_;
  double cost_per_metre_ = 0.0;
};

}  // namespace ifar::interaction
