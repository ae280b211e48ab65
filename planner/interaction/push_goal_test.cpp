#include "planner/interaction/push_goal_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "common/geometry/angle.hpp"
#include "planner/interaction/body_frame.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/ring_stretches.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Pose2;
using geometry::Vector;

namespace {

/// The way on may grow by going round the pushed object and by this much more: a way round through the
/// rooms beside a corridor is no way on (a box pushed along a corridor, leaving less than the vehicle's
/// width either side, would otherwise pass the check through rooms that lead round it).
constexpr double kOnwardDetourSlackM = 2.0;

}  // namespace

PushGoalTest::PushGoalTest(const PushProblemObject& problem, const PushObject& object,
                           const PushCollisionChecker& checker, const PusherSettings& pusher,
                           const SearchSettings& search, const ConnectivitySettings& limits,
                           bool onward_check)
    : footprint_(object.model().footprint),
      start_pose_(object.model().pose),
      inflation_m_(pusher.inflation_m),
      clearance_m_(pusher.inflation_m + search.passage_margin_m - search.penetration_tolerance_m),
      waypoint_search_cells_(static_cast<int>(std::ceil(pusher.inflation_m / kRasterResolutionM)))
{
  if (!onward_check) {
    return;
  }
  Bounds surroundings = boundsOf(problem.object);
  const double reach = surroundingsReach(limits, search);
  surroundings.minimum -= Point::Constant(reach);
  surroundings.maximum += Point::Constant(reach);
  surroundings_.emplace(surroundings, kRasterResolutionM);
  checker.rasterise(*surroundings_, surroundings);
}

PushGoalRegion PushGoalTest::region(const Point& start, const Point& goal) const
{
  PushGoalRegion region;
  region.segment = geometry::Segment{start, goal};
  const Vector along = (goal - start).normalized();
  const Vector across(-along.y(), along.x());
  const double half = inflation_m_;
  region.window = {start - along * half - across * half, goal + along * half - across * half,
                   goal + along * half + across * half, start - along * half + across * half};
  findOutlets(region);
  return region;
}

bool PushGoalTest::reached(const Pose2& pose, const PushGoalRegion& region) const
{
  return passageClear(pose, region) && onwardOpen(pose, region);
}

bool PushGoalTest::passageClear(const Pose2& pose, const PushGoalRegion& region) const
{
  return segmentPolygonDistance(region.segment, transformed(footprint_, pose)) >= clearance_m_;
}

void PushGoalTest::findOutlets(PushGoalRegion& region) const
{
  if (!surroundings_) {
    return;
  }
  FreeSpaceRaster unmoved = *surroundings_;
  unmoved.mark(unmoved.cellsNear(transformed(footprint_, start_pose_), clearance_m_),
               FreeSpaceRaster::kMovable);
  int components = 0;
  const std::vector<int> labels =
      unmoved.labelComponents(FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable, components);
  const auto start_cell = unmoved.nearestLabelled(region.segment.start, labels, waypoint_search_cells_);
  const auto goal_cell = unmoved.nearestLabelled(region.segment.end, labels, waypoint_search_cells_);
  if (!start_cell || !goal_cell) {
    return;
  }
  // The waypoints may share one component, joined round the object (through a room, or a stretch of
  // wall not seen yet): a push can still close the way on beyond them, so their outlets count all the same.
  // Each stretch of free edge cells is an outlet of its own: a push that closes the corridor on one
  // side of the object while a side room keeps the same side open still cuts a way on.
  const std::vector<std::size_t> ring = unmoved.borderCells();
  if (ring.empty()) {
    return;
  }
  const auto kept = [&](std::size_t cell) {
    return labels[cell] >= 0 && (labels[cell] == labels[*start_cell] || labels[cell] == labels[*goal_cell]);
  };
  const std::vector<int> stretches = ringStretches(ring, kept, region.outlet_count);
  region.outlets.assign(unmoved.cellCount(), 0);
  for (std::size_t position = 0; position < ring.size(); ++position) {
    region.outlets[ring[position]] = stretches[position];
  }
  limitOutletSteps(region);
}

void PushGoalTest::limitOutletSteps(PushGoalRegion& region) const
{
  // How far each outlet is with the object gone: the pushed object may lengthen that by going round it.
  region.outlet_step_limits.assign(static_cast<std::size_t>(region.outlet_count) + 1,
                                   std::numeric_limits<int>::max());
  const auto open_start =
      surroundings_->nearestFree(region.segment.start, FreeSpaceRaster::kObstacle, waypoint_search_cells_);
  if (!open_start) {
    return;
  }
  const int detour = onwardDetourSteps();
  int unmeasured = region.outlet_count;
  surroundings_->searchFrom(*open_start, FreeSpaceRaster::kObstacle, [&](std::size_t cell, int steps) {
    const auto outlet = static_cast<std::size_t>(region.outlets[cell]);
    if (outlet != 0 && region.outlet_step_limits[outlet] == std::numeric_limits<int>::max()) {
      region.outlet_step_limits[outlet] = steps + detour;
      --unmeasured;
    }
    return unmeasured == 0;
  });
}

int PushGoalTest::onwardDetourSteps() const
{
  double reach = 0.0;
  for (const Point& vertex : footprint_) {
    reach = std::max(reach, vertex.norm());
  }
  // Half way round the object's disc grown by the clearance, in 4-neighbour steps (up to sqrt(2) times
  // the straight length), plus the slack.
  const double detour_m = geometry::kPi * (reach + clearance_m_) + kOnwardDetourSlackM;
  return static_cast<int>(std::ceil(std::sqrt(2.0) * detour_m / kRasterResolutionM));
}

bool PushGoalTest::onwardOpen(const Pose2& pose, const PushGoalRegion& region) const
{
  if (!surroundings_ || region.outlet_count == 0) {
    return true;
  }
  const Polygon footprint = transformed(footprint_, pose);
  // An object with a free cell between it and every obstacle (and the raster's edge) is an island: it
  // cannot cut free space apart.
  const std::vector<FreeSpaceRaster::CellDistance> neighbourhood =
      surroundings_->cellDistancesNear(footprint, clearance_m_ + 1.5 * kRasterResolutionM);
  if (std::none_of(neighbourhood.begin(), neighbourhood.end(),
                   [&](const FreeSpaceRaster::CellDistance& near) {
                     return (surroundings_->layers(near.cell) & FreeSpaceRaster::kObstacle) != 0 ||
                            surroundings_->onBorder(near.cell);
                   })) {
    return true;
  }
  // The cells the moved object covers are closed to the search (the surroundings carry obstacles only).
  std::vector<std::size_t> covered;
  covered.reserve(neighbourhood.size());
  for (const FreeSpaceRaster::CellDistance& near : neighbourhood) {
    if (near.distance_m <= clearance_m_) {
      covered.push_back(near.cell);
    }
  }
  std::sort(covered.begin(), covered.end());
  const std::uint8_t blocked = FreeSpaceRaster::kObstacle;
  const auto start_cell =
      surroundings_->nearestFree(region.segment.start, blocked, waypoint_search_cells_, covered);
  if (!start_cell) {
    return false;
  }
  std::vector<bool> reached(static_cast<std::size_t>(region.outlet_count) + 1, false);
  int missing = region.outlet_count;
  bool too_far = false;
  // Nearest first: an outlet's first cell is as near as it gets.
  surroundings_->searchFrom(*start_cell, blocked, covered, onward_search_, [&](std::size_t cell, int steps) {
    const auto outlet = static_cast<std::size_t>(region.outlets[cell]);
    if (outlet != 0 && !reached[outlet]) {
      if (steps > region.outlet_step_limits[outlet]) {
        too_far = true;
        return true;
      }
      reached[outlet] = true;
      --missing;
    }
    return missing == 0;
  });
  return missing == 0 && !too_far;
}

}  // namespace ifar::interaction
