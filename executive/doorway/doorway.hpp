#pragma once
// Doorways: gaps across the path only a little wider than the vehicle. The follower's arcs keep a
// clearance that a 1.0 m door leaves to a 0.7 m vehicle only when it is centred and square to the door,
// and the global path crosses a door at a slant (it bends at the posts' inflated corners), so the vehicle
// wedged its corners on the posts and lost 10-35 s at each such door. The executive instead
// drives such a door as a straight run: to a point before the door on the best straight line through it,
// turn on the spot to the line's heading, then along the line to a point beyond the door.
//
// findDoorway is a pure function of the path ahead and the obstacle points.

#include <optional>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "executive/follower/footprint.hpp"

namespace ifar::executive {

struct DoorwaySettings {
  bool enabled = true;
  double max_width_m =
      1.2;  ///< a gap across the path narrower than this (between its two posts) is a doorway
  double look_ahead_m = 3.0;      ///< the path is searched for doorways this far ahead of the vehicle
  double min_ahead_m = 0.8;       ///< ... from this far (one the vehicle stands in is not started again)
  double approach_m = 1.0;        ///< the straight run starts this far before the door's centre
  double exit_m = 1.0;            ///< and ends this far beyond it
  double max_skew_rad = 0.45;     ///< the run may be this far off square to the line between the posts
  double min_clearance_m = 0.05;  ///< the footprint swept along the run keeps at least this from points
  double speed = 0.6;             ///< m/s along the run
  double timeout_s = 20.0;        ///< a run not done by then is given up and the door left to the follower
  double retry_after_s = 30.0;    ///< ... and not run again for this long
  double retry_radius_m = 0.5;    ///< ... a doorway found within this of its centre being the same door
  /// Arriving at the run's start at speed and within this of its heading, the lane tracker turns the rest
  /// while moving (a stop and a turn on the spot cost 2-4 s a door) ...
  double run_heading_tolerance_rad = 0.3;
  double run_start_tolerance_m = 0.15;  ///< ... and within this of the start (or the approach's tolerance)
  double run_end_tolerance_m = 0.1;     ///< the run is done this close (along it) to its end
  /// Through the door, the waypoints up to exit_m + waypoint_tolerance_m beyond it and within approach_m +
  /// exit_m + this of its centre are behind (the posts' and the run's own).
  double passed_margin_m = 0.5;
  /// A gap line within asin(this) (20 degrees) of the path's direction is one the path runs along, not
  /// through.
  double min_crossing_sine = 0.34;
};

struct Doorway {
  geometry::Point centre = geometry::Point::Zero();   ///< where the run crosses the line between the posts
  geometry::Point heading = geometry::Point::Zero();  ///< unit direction of the run, the way through
  double width_m = 0.0;                               ///< distance between the posts
  double clearance_m = 0.0;  ///< least distance of a point to the footprint swept along the run
  geometry::Point first_post = geometry::Point::Zero();
  geometry::Point second_post = geometry::Point::Zero();

  geometry::Point runStart(const DoorwaySettings& settings) const
  {
    return centre - settings.approach_m * heading;
  }
  geometry::Point runEnd(const DoorwaySettings& settings) const { return centre + settings.exit_m * heading; }
  /// Signed distance of `point` along the run from the centre (negative before the door).
  double along(const geometry::Point& point) const { return heading.dot(point - centre); }
};

/// The narrowest gap (post to post) the footprint is driven through: its width plus twice the doorway
/// clearance. Doorway runs and impassable-gap reports share it.
inline double passableWidth(const Footprint& footprint, const DoorwaySettings& settings)
{
  return 2.0 * (footprint.half_width_m + settings.min_clearance_m);
}

/// A gap across the path too narrow for the footprint however it is driven (narrower than its width plus
/// twice the doorway clearance) but not by more than that clearance narrower than its width: the planner's
/// inflation by the half width leaves such a gap open, e.g. beside a box pushed into a corridor, and
/// following stalls in it. Narrower ones the inflation closes as soon as the planner sees them.
struct ImpassableGap {
  geometry::Point first_post = geometry::Point::Zero();
  geometry::Point second_post = geometry::Point::Zero();
  double width_m = 0.0;  ///< distance between the posts
  double along_m = 0.0;  ///< path length from path[0] to where the path crosses the gap
};

/// The first impassable gap the path crosses between the footprint's front and `settings.look_ahead_m`
/// ahead of path[0], where the path runs between the two posts (not past their ends); None when there is
/// none. Independent of `settings.enabled` (only min_clearance_m and look_ahead_m are used).
std::optional<ImpassableGap> findImpassableGap(common::Span<const geometry::Point> path,
                                               common::Span<const geometry::Point> obstacles,
                                               const Footprint& footprint, const DoorwaySettings& settings);

/// The first doorway the path crosses between `settings.min_ahead_m` and `settings.look_ahead_m` ahead of
/// path[0] (the vehicle's position; then the waypoints still ahead, in order), with the straight run
/// through it that keeps the swept `footprint` furthest from `obstacles` (world-frame points). None when
/// the path crosses no gap narrower than max_width_m there, when the narrowest gap is too narrow for the
/// footprint, or when no straight run within max_skew_rad keeps min_clearance_m.
std::optional<Doorway> findDoorway(common::Span<const geometry::Point> path,
                                   common::Span<const geometry::Point> obstacles, const Footprint& footprint,
                                   const DoorwaySettings& settings);

}  // namespace ifar::executive
