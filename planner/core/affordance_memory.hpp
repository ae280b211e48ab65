#pragma once
// What AFFORDANCE taught the planner about an object, kept when the tracker loses the object: an
// unpushable box hidden behind a wall for a few frames comes back under a new id, and without this the
// vehicle would plan to push it again (and try, and fail) every time it lost sight of it.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "planner/core/object_tracker.hpp"
#include "planner/interaction/interaction_settings.hpp"

namespace ifar::planner {

struct LearnedAffordance {
  bool pushable = true;
  interaction::ObjectPhysics physics;
  std::optional<geometry::Point> centroid;  // where the object was last seen
};

class AffordanceMemory {
 public:
  /// A new object whose centroid is within `match_distance_m` of a lost one is taken to be it.
  explicit AffordanceMemory(double match_distance_m);

  /// An accepted AFFORDANCE for a tracked object last seen at `centroid`.
  void learned(std::int64_t object_id, bool pushable, const interaction::ObjectPhysics& physics,
               const std::optional<geometry::Point>& centroid);
  /// This frame's objects: the centroids of the ones with something learned are kept current.
  void seen(const std::vector<TrackedObject>& objects);
  /// The tracker dropped the object: what was learned waits for an object that appears where it was.
  void dropped(std::int64_t object_id);
  /// For an object the memory does not know: the lost object's learning nearest its centroid (within the
  /// match distance), now held under `object_id`; empty when there is none.
  std::optional<LearnedAffordance> inherit(std::int64_t object_id, const geometry::Point& centroid);

  std::size_t lostObjects() const { return lost_.size(); }

 private:
  double match_distance_m_;
  std::map<std::int64_t, LearnedAffordance> tracked_;
  std::vector<LearnedAffordance> lost_;
};

}  // namespace ifar::planner
