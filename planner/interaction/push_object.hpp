#pragma once
// The object one push search moves (paper VI.C, Problem 3): its model, limit surface and stable pushes
// per contact edge, where the vehicle stands to push each edge, how a push at an edge moves it, and the
// paths that drive the vehicle round it from one edge to another. Built once per object; every method
// is const, so the searches of all waypoint pairs share it.

#include <array>
#include <cstddef>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/object_model.hpp"
#include "planner/interaction/plan_status.hpp"
#include "planner/interaction/stable_push.hpp"

namespace ifar::interaction {

/// What a push search is given about one object, world frame of the local layer.
struct PushProblemObject {
  geometry::Polygon object;                  ///< inflated world polygon of the pushed object
  std::vector<geometry::Polygon> obstacles;  ///< inflated world polygons it must not run into
  ObjectPhysics physics;
};

/// The vehicle's reference point driving round the object from one contact edge to another, body frame.
struct SwitchPath {
  std::vector<geometry::Point> samples;  ///< points every boundary_sample_m, both standing points included
  double length = 0.0;
};

/// An object seen only as a face (ObjectModel::depth_seen false): the face's two ends and one of its
/// normals, body frame. The face is the footprint's longest edge, its ends on the line through the
/// centroid.
struct ObjectFace {
  std::array<geometry::Point, 2> ends{};
  geometry::Vector normal = geometry::Vector::UnitY();
};

class PushObject {
 public:
  PushObject(const PushProblemObject& problem, const PusherSettings& pusher, const SearchSettings& search,
             const ConnectivitySettings& limits);

  /// Found when the object can be pushed at all; otherwise why not (bad polygon or physics, too heavy,
  /// no stable contact). The parts below are only complete when Found.
  PlanStatus status() const { return status_; }
  const ObjectModel& model() const { return model_; }
  const std::vector<EdgePushOptions>& edgeOptions() const { return options_; }
  /// The least force any stable push of the object takes (N).
  double smallestForce() const { return smallest_force_n_; }
  /// Only meaningful when the model's depth_seen is false; a default face otherwise.
  const ObjectFace& face() const { return face_; }

  /// Where the vehicle's reference point stands to push `edge`: clear of the inflated object, body frame.
  geometry::Point standingPoint(std::size_t edge) const;
  /// The vehicle's reference pose pushing `edge` of the object at `object_pose`.
  geometry::Pose2 vehiclePose(const geometry::Pose2& object_pose, std::size_t edge) const;
  /// The object at `pose` pushed straight at `edge` for `distance` metres.
  geometry::Pose2 pushedStraight(const geometry::Pose2& pose, std::size_t edge, double distance) const;
  /// The object at `pose` pushed at `edge` along `distance` metres of an arc of the vehicle's reference
  /// point of `radius` metres (positive: turning left); the rotation centre lies on the vehicle's axle line.
  geometry::Pose2 pushedOnArc(const geometry::Pose2& pose, std::size_t edge, double radius,
                              double distance) const;
  /// Driving round the object from `from` to `to`: [0] counter-clockwise, [1] clockwise.
  const std::array<SwitchPath, 2>& switchPaths(std::size_t from, std::size_t to) const
  {
    return switch_paths_[from][to];
  }

 private:
  void buildSwitchPaths(double sample_spacing_m);

  PlanStatus status_ = PlanStatus::Found;
  PusherSettings pusher_;
  double contact_clearance_m_ = 0.0;
  ObjectModel model_;
  LimitSurface limit_surface_;
  std::vector<EdgePushOptions> options_;
  double smallest_force_n_ = 0.0;
  ObjectFace face_;
  /// switch_paths_[from][to][direction]: driving counter-clockwise (0) or clockwise (1).
  std::vector<std::vector<std::array<SwitchPath, 2>>> switch_paths_;
};

}  // namespace ifar::interaction
