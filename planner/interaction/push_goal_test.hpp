#pragma once
// When a push search has reached its goal (paper VI.C): the passage between the two waypoints, widened
// by the vehicle's half width and a margin, is clear of the object, and the object leaves the way on
// open: pushed along a corridor it would close the corridor further on, so where either side's free space
// reached beyond the surroundings before the push, the start waypoint must still reach it, and not much
// farther round than with the object gone. Built once per object; every test is const, and the tests of one
// PushGoalTest run on one thread (the onward check keeps its search buffers between calls).

#include <optional>

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"
#include "planner/interaction/free_space_raster.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_collision_checker.hpp"
#include "planner/interaction/push_goal_region.hpp"
#include "planner/interaction/push_object.hpp"

namespace ifar::interaction {

class PushGoalTest {
 public:
  /// Cell size of the rasters that judge the way on: about a fifth of the vehicle's width still tells a
  /// lane it fits from none, and keeps the check at every goal candidate cheap.
  static constexpr double kRasterResolutionM = 0.15;

  /// With `onward_check` the object's surroundings are rasterised once, out to beyond the farthest push,
  /// for onwardOpen; without, only the passage counts (a strategy that judges the way on itself).
  PushGoalTest(const PushProblemObject& problem, const PushObject& object,
               const PushCollisionChecker& checker, const PusherSettings& pusher,
               const SearchSettings& search, const ConnectivitySettings& limits, bool onward_check);

  /// The goal region of the waypoint pair `start` -> `goal`.
  PushGoalRegion region(const geometry::Point& start, const geometry::Point& goal) const;
  /// passageClear and onwardOpen.
  bool reached(const geometry::Pose2& pose, const PushGoalRegion& region) const;
  /// The object at `pose` keeps objectClearance() from the passage segment.
  bool passageClear(const geometry::Pose2& pose, const PushGoalRegion& region) const;
  /// Every outlet of `region` is still reachable from the start waypoint within its step limit.
  bool onwardOpen(const geometry::Pose2& pose, const PushGoalRegion& region) const;
  /// How far the object's footprint must stay from the passage: the vehicle's half width and a margin.
  double objectClearance() const { return clearance_m_; }
  /// How many raster cells round a waypoint to look for its free cell: a waypoint sits about the
  /// inflation from the object, so its cell may be covered.
  int waypointSearchCells() const { return waypoint_search_cells_; }

 private:
  /// Each stretch of the raster's edge where the free space on either side of the unmoved object leaves
  /// it: the pushed object must leave every one reachable from the start waypoint, and not much farther.
  void findOutlets(PushGoalRegion& region) const;
  /// How far each outlet is from the start waypoint with the object gone, plus the detour allowed.
  void limitOutletSteps(PushGoalRegion& region) const;
  /// How many raster steps longer than with the object gone the way to an outlet may be: round the
  /// object and a slack.
  int onwardDetourSteps() const;

  geometry::Polygon footprint_;  ///< body frame
  geometry::Pose2 start_pose_;   ///< the unmoved object
  double inflation_m_ = 0.0;
  double clearance_m_ = 0.0;
  int waypoint_search_cells_ = 0;
  /// The obstacles around the object, out to beyond the farthest push, for the onward check.
  std::optional<FreeSpaceRaster> surroundings_;
  /// The onward check's search buffers, kept from one pose to the next: the const tests of one
  /// PushGoalTest run on one thread (each planning builds its own).
  mutable FreeSpaceRaster::SearchScratch onward_search_;
};

}  // namespace ifar::interaction
