#pragma once
// A movable object's returns seen from farther hold its class when the vehicle comes closer. Nearer than
// the range at which the lidar's lowest laser meets the obstacle band's bottom (face_range_m: lidar
// height less ground clearance over the tangent of that laser's depression), the lasers pass over the
// foot of a face, and the nearer, the less of it they show: at the push's stand-off point a low box shows
// only a strip under its top edge, while the upper lasers still see the walls and door posts beside and
// behind it. Each missed tag of that strip (a tag's return read diffuse) is then outvoted by those walls
// in the tag neighbourhood, the face reads as wall, the object's door is closed in the free-space
// analysis and its push edges go just before contact. So each object keeps where its tagged returns, and
// the background's returns around them (inside its inflated outline: door posts, the wall behind), lay
// in the scan that showed most of its face: the latest one from at least as far as any before (every
// scan from beyond the face range shows all of it). While the sensor is nearer to those returns than
// that scan was, and within the face range, a return read untagged within `margin_m` of a held tagged
// one (the lidar's range noise and the pose's jitter between the two scans) and nearer to it than to
// any held background return is the object's (perception's HeldReturns): a missed tag on the face, not
// the post beside it. What this scan's rays pass through (the object was pushed or is not there) is no
// longer held; a push reported (AFFORDANCE) or the object dropped ends its hold.

#include <cstdint>
#include <map>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "common/vehicle.hpp"
#include "planner/core/object_tracker.hpp"
#include "planner/perception/free_space_view.hpp"

namespace ifar::planner {

struct TagHoldSettings {
  /// Nearer than this (horizontal range from the lidar, metres) the lowest laser passes over the foot
  /// of a face; 0 holds nothing.
  double face_range_m = 0.0;
  /// A return this close to a held one is the same object's (metres).
  double margin_m = 0.1;

  /// From the vehicle's lidar mount and obstacle band and the sensor's lowest laser (VLP-16: -15 deg).
  static TagHoldSettings fromVehicle(const common::VehicleSettings& vehicle, double margin_m);
};

class TagHold {
 public:
  explicit TagHold(const TagHoldSettings& settings) : settings_(settings) {}

  /// The held returns of the objects that have one within face range of `sensor` (ground plane, world
  /// frame) and nearer than the scan they were held from: what perception reads missed tags by.
  struct Returns {
    std::vector<geometry::Point> movable;
    std::vector<geometry::Point> background;
  };
  Returns heldNear(const geometry::Point& sensor) const;

  /// After tracking: each seen object whose movable returns of this scan (`movable`, ground plane, with
  /// their heights above the ground; by their tags alone, not those the hold took) inside its outline lie
  /// as far from `sensor` as those held (or at face range) or farther is held as seen now, with this
  /// scan's `background` returns inside its outline.
  void observe(const std::vector<TrackedObject>& seen, common::Span<const geometry::Point> movable,
               common::Span<const float> movable_heights_m, common::Span<const geometry::Point> background,
               const geometry::Point& sensor);

  /// Drops the held returns this scan's rays passed beyond (cells `cell_size_m` wide, rays no higher than
  /// the object's top): the object is not there any more. Returns how many went.
  std::size_t releaseSeenThrough(const perception::FreeSpaceView& view, double cell_size_m);

  void forget(std::int64_t object_id) { held_.erase(object_id); }
  bool holds(std::int64_t object_id) const { return held_.count(object_id) > 0; }
  /// Held returns of the object (empty for an object not held).
  std::vector<geometry::Point> heldOf(std::int64_t object_id) const;
  bool enabled() const { return settings_.face_range_m > 0.0 && settings_.margin_m > 0.0; }
  const TagHoldSettings& settings() const { return settings_; }

 private:
  struct Held {
    std::vector<geometry::Point> points;      // one per cell half a margin wide
    std::vector<geometry::Point> background;  // the same, of the background inside its outline
    double top_m = 0.0;                       // highest return seen of the object
    double range_m = 0.0;                     // the nearest from the sensor, at most the face range
  };

  TagHoldSettings settings_;
  std::map<std::int64_t, Held> held_;
};

}  // namespace ifar::planner
