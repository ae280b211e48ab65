#pragma once
// Whether a pushed object, or the vehicle driving round it, runs into the obstacles of its surroundings.
// Built once per object; every test is const, so the searches of all waypoint pairs share it.
//
// Object collision: footprint boundary points must not sit deeper inside an inflated obstacle than the
// inflation plus a rasterisation slack (the real object does not enter the real obstacle), nor cross the
// face of a wall perceived one cell thick (thin_wall.hpp). An object seen only as a face is taken to be
// unseen_depth_m deep beyond the face for this test, on the side away from where the push starts.

#include <array>
#include <cstddef>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"
#include "common/geometry/segment.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/free_space_raster.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_object.hpp"
#include "planner/interaction/thin_wall.hpp"

namespace ifar::interaction {

class PushCollisionChecker {
 public:
  /// Keeps the obstacles of `problem` a push of this search can come near. `object` must be Found.
  PushCollisionChecker(const PushProblemObject& problem, const PushObject& object,
                       const PusherSettings& pusher, const SearchSettings& search,
                       const ConnectivitySettings& limits);

  /// Whether the object moving from `from` to `to` enters an obstacle: deeper than the allowed depth at
  /// `to`, or through a thin wall's face on the way; `depth_side` picks the side of the face its unseen
  /// depth lies on (0: along ObjectFace::normal).
  bool objectCollides(const geometry::Pose2& from, const geometry::Pose2& to, std::size_t depth_side) const;
  /// An object seen only as a face, with both ends of the face close to walls at `pose` and a probe length
  /// further along `depth_direction` (body frame): it may not be turned, an arc would sweep the unseen
  /// depth into the walls of the passage it stands in.
  bool turnConfined(const geometry::Pose2& pose, const geometry::Vector& depth_direction) const;
  /// Whether `world` lies inside an (inflated) obstacle, farther than `depth` from its boundary.
  bool insideDeeperThan(const geometry::Point& world, double depth) const;
  /// Whether `world` lies inside an (inflated) obstacle: the vehicle's reference point cannot be there.
  bool pointBlocked(const geometry::Point& world) const;
  /// Whether the vehicle can drive `path` round the object standing at `pose`.
  bool switchFree(const geometry::Pose2& pose, const SwitchPath& path) const;
  /// Whether `segment` properly crosses an obstacle's edge.
  bool crossesAnObstacle(const geometry::Segment& segment) const;
  /// Marks the obstacles that overlap `window` in `raster` as FreeSpaceRaster::kObstacle.
  void rasterise(FreeSpaceRaster& raster, const Bounds& window) const;

 private:
  void keepReachableObstacles(const PushProblemObject& problem, double reach);
  /// A footprint recovered from a rasterised polygon may already sit a little inside a wall: allow what
  /// the start pose has, so "never hit an obstacle" means "never pushed deeper".
  void measureAllowedDepth(const std::vector<geometry::Point>& footprint_samples, double tolerance);
  /// An object seen only as a face reaches `unseen_depth_m` (less where a wall stands behind its face)
  /// on either side of the face, in collision_outlines_ and collision_samples_.
  void addUnseenDepth(const geometry::Polygon& footprint, double unseen_depth_m, double sample_spacing_m);
  void findThinWalls(double inflation);

  std::vector<geometry::Polygon> obstacles_;
  std::vector<Bounds> obstacle_bounds_;
  geometry::Pose2 start_pose_;  ///< the unmoved object
  bool depth_seen_ = true;
  ObjectFace face_;
  double inflation_m_ = 0.0;
  /// What collides, body frame: the footprint, with an object seen only as a face taken to be
  /// unseen_depth_m deep beyond the face along its normal ([0]) or against it ([1]).
  std::array<geometry::Polygon, 2> collision_outlines_;
  std::array<std::vector<geometry::Point>, 2> collision_samples_;
  /// How deep a footprint point may sit inside an inflated obstacle.
  double allowed_depth_m_ = 0.0;
  /// The obstacles no point of which lies deeper than allowed_depth_m_: walls perceived one cell thick.
  std::vector<ThinWall> thin_walls_;
};

}  // namespace ifar::interaction
