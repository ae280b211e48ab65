#include "planner/interaction/push_object.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planner/interaction/body_frame.hpp"
#include "planner/interaction/polyline_samples.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Pose2;
using geometry::Vector;

namespace {

/// The least force of any stable push at any edge; infinite when no edge has one.
double smallestStableForce(const std::vector<EdgePushOptions>& options)
{
  double smallest_force = std::numeric_limits<double>::infinity();
  for (const EdgePushOptions& option : options) {
    if (option.straight) {
      smallest_force = std::min(smallest_force, option.straight_force_n);
    }
    if (std::isfinite(option.left_radius_m)) {
      smallest_force = std::min(smallest_force, option.left_force_n);
    }
    if (std::isfinite(option.right_radius_m)) {
      smallest_force = std::min(smallest_force, option.right_force_n);
    }
  }
  return smallest_force;
}

ObjectFace seenFace(const geometry::Polygon& footprint)
{
  Vector along = Vector::UnitX();
  double longest = 0.0;
  for (std::size_t vertex = 0; vertex < footprint.size(); ++vertex) {
    const Vector edge = footprint[(vertex + 1) % footprint.size()] - footprint[vertex];
    if (edge.norm() > longest) {
      longest = edge.norm();
      along = edge / longest;
    }
  }
  double low = 0.0;
  double high = 0.0;
  for (const Point& vertex : footprint) {
    low = std::min(low, vertex.dot(along));
    high = std::max(high, vertex.dot(along));
  }
  ObjectFace face;
  face.ends = {Point(along * low), Point(along * high)};
  face.normal = Vector(-along.y(), along.x());
  return face;
}

}  // namespace

PushObject::PushObject(const PushProblemObject& problem, const PusherSettings& pusher,
                       const SearchSettings& search, const ConnectivitySettings& limits)
    : pusher_(pusher), contact_clearance_m_(search.contact_clearance_m)
{
  status_ = checkPhysics(problem.physics, pusher);
  if (status_ != PlanStatus::Found) {
    return;
  }
  const ObjectModelResult built =
      buildObjectModel(problem.object, pusher, limits, search.contact_clearance_m);
  status_ = built.status;
  if (status_ != PlanStatus::Found) {
    return;
  }
  model_ = built.model;
  limit_surface_ = ellipsoidalLimitSurface(model_.footprint, problem.physics);
  if (limit_surface_.max_force_n > pusher.max_push_force_n) {
    status_ = PlanStatus::TooHeavy;
    return;
  }
  options_ = edgePushOptions(model_.footprint, pusher, limit_surface_);
  smallest_force_n_ = smallestStableForce(options_);
  if (!std::isfinite(smallest_force_n_)) {
    status_ = PlanStatus::NoStableContact;
    return;
  }
  if (!model_.depth_seen) {
    face_ = seenFace(model_.footprint);
  }
  buildSwitchPaths(search.boundary_sample_m);
}

void PushObject::buildSwitchPaths(double sample_spacing_m)
{
  const std::size_t count = model_.footprint.size();
  switch_paths_.assign(count, std::vector<std::array<SwitchPath, 2>>(count));
  for (std::size_t from = 0; from < count; ++from) {
    for (std::size_t to = 0; to < count; ++to) {
      if (from == to) {
        continue;
      }
      std::vector<Point> counter_clockwise{standingPoint(from)};
      for (std::size_t vertex = (from + 1) % count;; vertex = (vertex + 1) % count) {
        counter_clockwise.push_back(model_.travel_outline[vertex]);
        if (vertex == to) {
          break;
        }
      }
      counter_clockwise.push_back(standingPoint(to));
      std::vector<Point> clockwise{standingPoint(from)};
      for (std::size_t vertex = from;; vertex = (vertex + count - 1) % count) {
        clockwise.push_back(model_.travel_outline[vertex]);
        if (vertex == (to + 1) % count) {
          break;
        }
      }
      clockwise.push_back(standingPoint(to));
      std::array<SwitchPath, 2>& paths = switch_paths_[from][to];
      samplePolyline(counter_clockwise, sample_spacing_m, paths[0].samples, paths[0].length);
      samplePolyline(clockwise, sample_spacing_m, paths[1].samples, paths[1].length);
    }
  }
}

Point PushObject::standingPoint(std::size_t edge) const
{
  const ContactPatch& patch = options_[edge].patch;
  return patch.middle - patch.push_direction * (pusher_.inflation_m + contact_clearance_m_);
}

Pose2 PushObject::vehiclePose(const Pose2& object_pose, std::size_t edge) const
{
  const ContactPatch& patch = options_[edge].patch;
  const Point axle = object_pose.transform(patch.middle - patch.push_direction * pusher_.bumper_to_axle_m);
  const Vector heading = rotate(patch.push_direction, object_pose.heading);
  return Pose2{axle.x(), axle.y(), std::atan2(heading.y(), heading.x())};
}

Pose2 PushObject::pushedStraight(const Pose2& pose, std::size_t edge, double distance) const
{
  const Vector direction = rotate(options_[edge].patch.push_direction, pose.heading);
  return Pose2{pose.x + direction.x() * distance, pose.y + direction.y() * distance, pose.heading};
}

Pose2 PushObject::pushedOnArc(const Pose2& pose, std::size_t edge, double radius, double distance) const
{
  const Pose2 vehicle = vehiclePose(pose, edge);
  const Vector left(-std::sin(vehicle.heading), std::cos(vehicle.heading));
  const Point centre = vehicle.position() + left * radius;
  return rotateAbout(pose, centre, distance / radius);
}

}  // namespace ifar::interaction
