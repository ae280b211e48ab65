#pragma once
// A movable object seen in part (a face hidden behind a wall, a side seen edge-on) looks smaller than it
// is, and which part shows changes with the view: a lane beside a box that plugs a corridor opens and
// closes as the vehicle moves, and the path flips with it, so the vehicle circles in front of it. Each
// object keeps the convex hull of its outlines since the vehicle was last at it, so a lane once seen
// closed stays closed. Near the object (where the vehicle pushes it) the hull restarts from the outline
// of the frame: a pushed object moves, and its old outlines would smear along the push.

#include <cstdint>
#include <unordered_map>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"

namespace ifar::planner {

class OutlineMemory {
 public:
  /// `restart_distance_m`: the vehicle this close to an object's outline (or inside it) restarts its hull;
  /// 0 keeps no memory (every outline is used as seen).
  explicit OutlineMemory(double restart_distance_m) : restart_distance_m_(restart_distance_m) {}

  /// The outline to plan with for object `id`, seen this frame as `outline` (world frame) with the vehicle
  /// at `vehicle`: the convex hull of this outline and those remembered since the last restart.
  geometry::Polygon remember(std::int64_t id, const geometry::Polygon& outline,
                             const geometry::Point& vehicle);
  void forget(std::int64_t id) { hulls_.erase(id); }
  /// False when constructed with 0: remember() gives every outline back as seen.
  bool enabled() const { return restart_distance_m_ > 0.0; }
  std::size_t size() const { return hulls_.size(); }

 private:
  double restart_distance_m_;
  std::unordered_map<std::int64_t, geometry::Polygon> hulls_;
};

}  // namespace ifar::planner
