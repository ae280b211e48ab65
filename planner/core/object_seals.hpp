#pragma once
// Blocked passages beside a movable object. When the gap the vehicle could not get through is bounded by
// a movable object, a row of background cells would be a wall for good: it stays when the object moves,
// and the object no longer plugs the passage (the seal does), so no push is ever planned to widen it.
// Such a seal is kept with the object instead: the object's inflated outline takes in the gap's free
// cells (the room beside it that the vehicle cannot use), so the object plugs the passage, and the graph
// routes round it or through a push that widens the gap. The seal goes when the object is pushed (the gap
// beside it changed); when the object turns out unpushable or is lost, its cells become an ordinary seal.

#include <cstdint>
#include <map>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"

namespace ifar::planner {

class ObjectSeals {
 public:
  explicit ObjectSeals(double cell_size_m) : cell_size_m_(cell_size_m) {}

  /// Keeps a seal with `object_id`: its outline takes in the cells `gap` (centres, `cell_size_m` wide);
  /// `cells` are the whole seal's, for release().
  void bind(std::int64_t object_id, const std::vector<geometry::Point>& gap,
            const std::vector<geometry::Point>& cells);
  bool holds(std::int64_t object_id) const { return seals_.count(object_id) > 0; }
  /// The object's outline with its gap cells: their convex hull; `outline` itself without a seal.
  geometry::Polygon grown(std::int64_t object_id, const geometry::Polygon& outline) const;
  /// Drops the object's seal and returns its cells (empty when it had none).
  std::vector<geometry::Point> release(std::int64_t object_id);
  void clear() { seals_.clear(); }
  std::size_t size() const { return seals_.size(); }

 private:
  struct Seal {
    std::vector<geometry::Point> gap;
    std::vector<geometry::Point> cells;
  };
  double cell_size_m_;
  std::map<std::int64_t, Seal> seals_;
};

}  // namespace ifar::planner
