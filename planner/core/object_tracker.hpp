#pragma once
// Stable ids for movable objects across frames. Perception gives this frame's movable outlines with no
// identity; the tracker associates them with the objects of the previous frames by centroid distance
// and bounding-box overlap, so the id the graph loops, the interaction edges and the daemon's messages
// carry stays the same while the vehicle moves. Outlines the sensor split (several near one object) keep
// the object's id; objects whose outlines touch (one outline covering several objects) are not counted
// as missing. An object unseen while in view (within the radius and, when the caller can tell, in sight)
// for `drop_after_frames` frames is dropped.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/geometry/segment.hpp"

namespace ifar::planner {

struct TrackerSettings {
  double association_distance_m = 1.0;  // largest centroid jump between frames of one object
  int drop_after_frames = 5;            // frames unseen while in view before the object is dropped
  double view_radius_m = 25.0;          // objects farther from the vehicle are not expected to be seen
};

/// One tracked object as seen this frame.
struct TrackedObject {
  std::int64_t id = 0;        // > 0, never reused
  geometry::Polygon outline;  // this frame's outline (convex hull when the sensor split it), world frame
  geometry::Point centroid = geometry::Point::Zero();
};

struct TrackingResult {
  std::vector<std::int64_t> polygon_ids;  // per input outline, the object id it belongs to
  std::vector<TrackedObject> seen;        // objects observed this frame, ascending id
  std::vector<std::int64_t> dropped;      // objects removed this frame (their edges must go)
};

class ObjectTracker {
 public:
  explicit ObjectTracker(const TrackerSettings& settings);

  /// Associates this frame's movable outlines (world frame) with the tracked objects. `in_sight` tells
  /// whether an unseen object's centroid could have been seen from the vehicle (empty: always): an
  /// object behind a wall is not missing, and must keep its id, edges and plans until it comes back.
  TrackingResult update(const std::vector<geometry::Polygon>& outlines, const geometry::Point& vehicle,
                        const std::function<bool(const geometry::Point&)>& in_sight = {});

  /// Removes an object now (e.g. its outline left the map); false for an unknown id.
  bool forget(std::int64_t id);
  bool contains(std::int64_t id) const;
  /// Where the object was last seen; empty for ids not tracked.
  std::optional<geometry::Point> centroidOf(std::int64_t id) const;
  /// The object's latest outline; empty for an unknown id.
  geometry::Polygon outlineOf(std::int64_t id) const;
  /// The object whose latest outline lies nearest to `segment`, when that is at most `radius` away.
  std::optional<std::int64_t> nearestTo(const geometry::Segment& segment, double radius) const;
  std::size_t size() const { return tracks_.size(); }

 private:
  struct Track {
    std::int64_t id = 0;
    geometry::Polygon outline;
    geometry::Point centroid = geometry::Point::Zero();
    int misses = 0;
  };

  TrackerSettings settings_;
  std::vector<Track> tracks_;  // ascending id
  std::int64_t next_id_ = 1;
};

}  // namespace ifar::planner
