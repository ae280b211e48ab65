#include "planner/interaction/push_collision_checker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "planner/interaction/body_frame.hpp"
#include "planner/interaction/polyline_samples.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Pose2;
using geometry::Vector;

namespace {

/// A face-only object is not turned while the ends of its face are closer than this to walls, both where
/// the face is and kConfinedFaceProbeM beyond it (away from where the push starts, where the unseen depth
/// lies): the turn would sweep that depth into the walls of a passage. A box in an office door (walls
/// 0.2 m thick) may still be turned at once: beyond the door its depth is in the open.
constexpr double kConfinedFaceGapM = 0.3;
constexpr double kConfinedFaceProbeM = 1.0;

}  // namespace

PushCollisionChecker::PushCollisionChecker(const PushProblemObject& problem, const PushObject& object,
                                           const PusherSettings& pusher, const SearchSettings& search,
                                           const ConnectivitySettings& limits)
    : start_pose_(object.model().pose),
      depth_seen_(object.model().depth_seen),
      face_(object.face()),
      inflation_m_(pusher.inflation_m)
{
  // Obstacles no push of this search comes near are left out: the scene may reach further, for a wider
  // search of the same object, and every collision test walks the list.
  keepReachableObstacles(problem, obstacleReach(limits, search, pusher));
  const Polygon& footprint = object.model().footprint;
  const std::vector<Point> footprint_samples = outlineSamples(footprint, search.boundary_sample_m);
  collision_samples_ = {footprint_samples, footprint_samples};
  collision_outlines_ = {footprint, footprint};
  measureAllowedDepth(footprint_samples, search.penetration_tolerance_m);
  if (!depth_seen_) {
    addUnseenDepth(footprint, search.unseen_depth_m, search.boundary_sample_m);
  }
  findThinWalls(pusher.inflation_m);
}

void PushCollisionChecker::keepReachableObstacles(const PushProblemObject& problem, double reach)
{
  Bounds reachable = boundsOf(problem.object);
  reachable.minimum -= Point::Constant(reach);
  reachable.maximum += Point::Constant(reach);
  for (const Polygon& obstacle : problem.obstacles) {
    const Bounds bounds = boundsOf(obstacle);
    if (bounds.overlaps(reachable)) {
      obstacles_.push_back(obstacle);
      obstacle_bounds_.push_back(bounds);
    }
  }
}

void PushCollisionChecker::measureAllowedDepth(const std::vector<Point>& footprint_samples, double tolerance)
{
  allowed_depth_m_ = inflation_m_ + tolerance;
  for (const Point& sample : footprint_samples) {
    const Point world = start_pose_.transform(sample);
    for (const Polygon& obstacle : obstacles_) {
      if (geometry::locatePoint(obstacle, world) == geometry::Containment::Inside) {
        allowed_depth_m_ =
            std::max(allowed_depth_m_, geometry::distanceToBoundary(obstacle, world) + tolerance);
      }
    }
  }
}

void PushCollisionChecker::addUnseenDepth(const Polygon& footprint, double unseen_depth_m,
                                          double sample_spacing_m)
{
  double near = 0.0;
  double far = 0.0;
  for (const Point& vertex : footprint) {
    near = std::min(near, vertex.dot(face_.normal));
    far = std::max(far, vertex.dot(face_.normal));
  }
  const double missing = unseen_depth_m - (far - near);
  if (!(missing > 0.0)) {
    return;
  }
  // Side 0 lies along the face's normal, side 1 against it. The depth stops where the object, standing
  // where it is, would enter a wall: it cannot be deeper than the room behind its face.
  const Vector along = (face_.ends[1] - face_.ends[0]).normalized();
  const double face_length = (face_.ends[1] - face_.ends[0]).norm();
  const int across = std::max(1, static_cast<int>(std::ceil(face_length / sample_spacing_m)));
  const int deep = std::max(1, static_cast<int>(std::ceil(missing / sample_spacing_m)));
  for (std::size_t side = 0; side < 2; ++side) {
    const Vector outward = side == 0 ? face_.normal : Vector(-face_.normal);
    const Point base = face_.ends[0] + outward * (side == 0 ? far : -near);
    double reached = 0.0;
    for (int step = 1; step <= deep; ++step) {
      const double depth = missing * step / deep;
      bool enters_wall = false;
      for (int point = 0; point <= across && !enters_wall; ++point) {
        const Point body = base + along * (face_length * point / across) + outward * depth;
        enters_wall = insideDeeperThan(start_pose_.transform(body), allowed_depth_m_);
      }
      if (enters_wall) {
        break;
      }
      reached = depth;
    }
    if (reached <= 0.0) {
      continue;
    }
    Polygon grown = footprint;
    grown.push_back(base + outward * reached);
    grown.push_back(base + along * face_length + outward * reached);
    collision_outlines_[side] = geometry::convexHull(grown);
    collision_samples_[side] = outlineSamples(collision_outlines_[side], sample_spacing_m);
  }
}

void PushCollisionChecker::findThinWalls(double inflation)
{
  for (const Polygon& obstacle : obstacles_) {
    std::optional<ThinWall> wall = thinWall(obstacle, inflation, allowed_depth_m_);
    if (!wall) {
      continue;
    }
    // A point of the unmoved object already inside the wall's inflation is not held to its face, as the
    // depth test allows what the start pose has: the outlines are perceived (a box 5 cm from each door
    // frame may be perceived reaching past one).
    for (std::size_t side = 0; side < 2; ++side) {
      for (const Point& sample : collision_samples_[side]) {
        const Point world = start_pose_.transform(sample);
        wall->exempt[side].push_back(wall->bounds.contains(world) &&
                                     geometry::locatePoint(obstacle, world) == geometry::Containment::Inside);
      }
    }
    thin_walls_.push_back(std::move(*wall));
  }
}

bool PushCollisionChecker::objectCollides(const Pose2& from, const Pose2& to, std::size_t side) const
{
  const BodyToWorld to_world(to);
  const Bounds after = boundsOf(transformed(collision_outlines_[side], to));
  for (std::size_t index = 0; index < obstacles_.size(); ++index) {
    if (!obstacle_bounds_[index].overlaps(after)) {
      continue;
    }
    for (const Point& sample : collision_samples_[side]) {
      const Point world = to_world(sample);
      if (obstacle_bounds_[index].contains(world) &&
          geometry::locatePoint(obstacles_[index], world) == geometry::Containment::Inside &&
          geometry::distanceToBoundary(obstacles_[index], world) > allowed_depth_m_) {
        return true;
      }
    }
  }
  if (thin_walls_.empty()) {
    return false;  // only a thin wall looks at where the move starts
  }
  const BodyToWorld from_world(from);
  const Bounds before = boundsOf(transformed(collision_outlines_[side], from));
  const Bounds swept{before.minimum.cwiseMin(after.minimum), before.maximum.cwiseMax(after.maximum)};
  for (const ThinWall& wall : thin_walls_) {
    if (!wall.bounds.overlaps(swept)) {
      continue;
    }
    for (std::size_t index = 0; index < collision_samples_[side].size(); ++index) {
      if (!wall.exempt[side][index] && wall.crossedBy(from_world(collision_samples_[side][index]),
                                                      to_world(collision_samples_[side][index]))) {
        return true;
      }
    }
  }
  return false;
}

bool PushCollisionChecker::turnConfined(const Pose2& pose, const Vector& depth_direction) const
{
  if (depth_seen_) {
    return false;
  }
  // A point of an inflated obstacle deeper than inflation - gap is closer than the gap to the wall.
  const double depth = inflation_m_ - kConfinedFaceGapM;
  const BodyToWorld to_world(pose);
  return std::all_of(face_.ends.begin(), face_.ends.end(), [&](const Point& end) {
    return insideDeeperThan(to_world(end), depth) &&
           insideDeeperThan(to_world(end + depth_direction * kConfinedFaceProbeM), depth);
  });
}

bool PushCollisionChecker::insideDeeperThan(const Point& world, double depth) const
{
  for (std::size_t index = 0; index < obstacles_.size(); ++index) {
    if (obstacle_bounds_[index].contains(world) &&
        geometry::locatePoint(obstacles_[index], world) == geometry::Containment::Inside &&
        geometry::distanceToBoundary(obstacles_[index], world) > depth) {
      return true;
    }
  }
  return false;
}

bool PushCollisionChecker::pointBlocked(const Point& world) const
{
  return insideDeeperThan(world, -std::numeric_limits<double>::infinity());
}

bool PushCollisionChecker::switchFree(const Pose2& pose, const SwitchPath& path) const
{
  const BodyToWorld to_world(pose);
  return std::none_of(path.samples.begin(), path.samples.end(),
                      [&](const Point& sample) { return pointBlocked(to_world(sample)); });
}

bool PushCollisionChecker::crossesAnObstacle(const geometry::Segment& segment) const
{
  for (const Polygon& obstacle : obstacles_) {
    for (std::size_t side = 0; side < obstacle.size(); ++side) {
      if (geometry::segmentsCrossProperly(segment, geometry::polygonEdge(obstacle, side))) {
        return true;
      }
    }
  }
  return false;
}

void PushCollisionChecker::rasterise(FreeSpaceRaster& raster, const Bounds& window) const
{
  for (std::size_t index = 0; index < obstacles_.size(); ++index) {
    if (obstacle_bounds_[index].overlaps(window)) {
      raster.fill(obstacles_[index], FreeSpaceRaster::kObstacle);
    }
  }
}

}  // namespace ifar::interaction
