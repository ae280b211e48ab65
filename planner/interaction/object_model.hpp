#pragma once
// The pushed object as the planner models it: the local layer gives its polygon inflated by the
// vehicle's half width; the physical footprint is recovered by shrinking the convex hull back.

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/plan_status.hpp"

namespace ifar::interaction {

/// Checks a polygon from the local layer: at least 3 vertices, finite, simple, not a sliver, and no
/// larger than the local layer. Returns Found when usable.
PlanStatus checkPolygon(const geometry::Polygon& polygon, const ConnectivitySettings& limits);

struct ObjectModel {
  /// Physical footprint in the body frame: convex, counter-clockwise, centroid (= centre of friction,
  /// uniform pressure) at the origin.
  geometry::Polygon footprint;
  /// Path of the vehicle's reference point when it drives round the object: the footprint grown by
  /// the inflation plus a clearance; vertex i lies between the grown edges i - 1 and i.
  geometry::Polygon travel_outline;
  /// World pose of the body frame (heading 0: body axes parallel to the world axes).
  geometry::Pose2 pose;
  /// False when the polygon was too thin to shrink by the whole inflation: only a face was seen and
  /// the footprint's depth is a guess.
  bool depth_seen = true;
};

struct ObjectModelResult {
  PlanStatus status = PlanStatus::DegeneratePolygon;
  ObjectModel model;
};

/// Builds the model from the inflated world polygon. A polygon thinner than 2.5 times the inflation
/// (a post, a rasterised sliver, an object seen only by its near face) is shrunk by 40 % of its width,
/// not by the whole inflation, so it keeps an area; its model then has depth_seen false.
ObjectModelResult buildObjectModel(const geometry::Polygon& inflated_world, const PusherSettings& pusher,
                                   const ConnectivitySettings& limits, double clearance_m);

}  // namespace ifar::interaction
