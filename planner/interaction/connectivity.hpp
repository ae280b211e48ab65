#pragma once
// Topological connectivity analysis (paper V.B): does a movable polygon split the nearby free space
// into n >= 2 components that join when it is removed? If so, one topological waypoint per component
// by Eq. 1 and the n(n-1) ordered waypoint pairs that need a push plan each.

#include <cstddef>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/plan_status.hpp"

namespace ifar::interaction {

/// The local layer: polygons already inflated by the vehicle's half width, in the world frame.
struct LocalScene {
  std::vector<geometry::Polygon> background;
  std::vector<geometry::Polygon> movable;
};

struct TopologicalWaypoint {
  geometry::Point position;        ///< p_topo: where the vehicle waits in this component
  geometry::Point boundary_point;  ///< p': where the normal leaves the movable polygon
  geometry::Vector normal;         ///< unit normal of the intersection-point chord, away from the object
  std::size_t component = 0;       ///< index of the free-space component, 0 .. n - 1
};

struct OrderedPair {
  std::size_t from = 0;  ///< waypoint index (equal to its component index)
  std::size_t to = 0;
};

struct ConnectivityResult {
  /// Found when the analysis ran (whether or not the object splits the space); DegeneratePolygon or
  /// ObjectTooLarge when the movable polygon cannot be analysed.
  PlanStatus status = PlanStatus::Found;
  bool splits = false;
  std::vector<TopologicalWaypoint> waypoints;  ///< waypoint i belongs to component i
  std::vector<OrderedPair> pairs;              ///< all n(n-1) ordered pairs
  std::size_t skipped_polygons = 0;            ///< degenerate neighbour polygons left out (counted, skipped)
};

/// Obstacles for movable `movable_index`: background plus every other movable polygon (they are not
/// pushed along). Degenerate polygons are skipped and counted in `skipped`.
std::vector<geometry::Polygon> obstaclesFor(const LocalScene& scene, std::size_t movable_index,
                                            const ConnectivitySettings& settings, std::size_t& skipped);

ConnectivityResult analyzeConnectivity(const LocalScene& scene, std::size_t movable_index,
                                       const ConnectivitySettings& settings);

}  // namespace ifar::interaction
