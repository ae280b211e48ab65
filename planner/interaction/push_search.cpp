#include "planner/interaction/push_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>

#include "common/geometry/angle.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Pose2;
using geometry::Segment;
using geometry::Vector;

namespace {

Pose2 rotateAbout(const Pose2& pose, const Point& centre, double angle)
{
  const double cosine = std::cos(angle);
  const double sine = std::sin(angle);
  const Vector offset = pose.position() - centre;
  return Pose2{centre.x() + cosine * offset.x() - sine * offset.y(),
               centre.y() + sine * offset.x() + cosine * offset.y(),
               geometry::wrapAngle(pose.heading + angle)};
}

Vector rotate(const Vector& vector, double angle)
{
  return Vector(std::cos(angle) * vector.x() - std::sin(angle) * vector.y(),
                std::sin(angle) * vector.x() + std::cos(angle) * vector.y());
}

Polygon transformed(const Polygon& body, const Pose2& pose)
{
  Polygon world;
  world.reserve(body.size());
  for (const Point& vertex : body) {
    world.push_back(pose.transform(vertex));
  }
  return world;
}

/// Points every `spacing` along a polyline (end points included).
void samplePolyline(const std::vector<Point>& polyline, double spacing, std::vector<Point>& samples,
                    double& length)
{
  length = 0.0;
  if (polyline.empty()) {
    return;
  }
  samples.push_back(polyline.front());
  for (std::size_t index = 1; index < polyline.size(); ++index) {
    const Vector step = polyline[index] - polyline[index - 1];
    const double segment_length = step.norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(segment_length / spacing)));
    for (int piece = 1; piece <= pieces; ++piece) {
      samples.push_back(polyline[index - 1] + step * (static_cast<double>(piece) / pieces));
    }
    length += segment_length;
  }
}

/// Points every `spacing` round a closed polygon, starting and ending at its first vertex.
std::vector<Point> outlineSamples(const Polygon& polygon, double spacing)
{
  std::vector<Point> outline = polygon;
  outline.push_back(polygon.front());
  std::vector<Point> samples;
  double perimeter = 0.0;
  samplePolyline(outline, spacing, samples, perimeter);
  return samples;
}

struct Node {
  Pose2 pose;
  std::size_t edge = 0;
  double cost = 0.0;
  int parent = -1;
  PushControl control;  ///< how this node was reached from its parent (unused for roots)
  bool root = false;
  double approach_m = 0.0;  ///< roots: travel from the start waypoint to the contact
};

struct QueueEntry {
  double priority;
  int node;
  bool operator>(const QueueEntry& other) const { return priority > other.priority; }
};

/// Cell size of the onward check's raster: about a fifth of the vehicle's width still tells a lane it
/// fits from none, and keeps the search at every goal candidate cheap (all pairs of the T-junction
/// bench: 7.1 ms median, 37 ms at 0.1 m).
constexpr double kSurroundingsResolutionM = 0.15;

/// The way on may grow by going round the pushed object and by this much more: a way round through the
/// rooms beside a corridor is no way on (office2x-3+4 t0: the fire-door box pushed 2 m along the corridor
/// left 0.77 m either side and passed the check through the rooms south of it; the vehicle stalled at the
/// box, then drove round through those rooms).
constexpr double kOnwardDetourSlackM = 2.0;

/// How far apart the corridor push judges the way on before refining (BM_BarInATunnelAllPairsCorridor:
/// every 0.4 m cost about 25 ms more for the bar's 38 m push).
constexpr double kCorridorJudgementStepM = 1.0;

/// An object seen only as a face is not turned while the ends of the face are closer than this to walls,
/// both where the face is and kConfinedFaceProbeM beyond it (away from where the push starts, where the
/// unseen depth lies): the turn would sweep that depth into the walls of the passage the object stands
/// in (driven Willow t3: a 1.2 m box in a 1.3 m, 6 m long passage, turned, jammed). A box in an office
/// door (walls 0.2 m thick) may still be turned at once: beyond the door its depth is in the open.
constexpr double kConfinedFaceGapM = 0.3;
constexpr double kConfinedFaceProbeM = 1.0;

/// Numbers the stretches of consecutive `ring` cells that pass `kept`: 1, 2, ... in order round it, 0 for
/// cells that fail. The walk starts after a failing cell, so no stretch is split where the ring closes; a
/// ring kept all round is one stretch. `count` is the number of stretches.
template <typename Kept>
std::vector<int> ringStretches(const std::vector<std::size_t>& ring, Kept&& kept, int& count)
{
  count = 0;
  std::vector<int> stretches(ring.size(), 0);
  std::size_t first = 0;
  while (first < ring.size() && kept(ring[first])) {
    ++first;
  }
  bool in_stretch = false;
  for (std::size_t step = 1; step <= ring.size(); ++step) {
    const std::size_t position = (first + step) % ring.size();
    if (!kept(ring[position])) {
      in_stretch = false;
      continue;
    }
    if (!in_stretch) {
      ++count;
      in_stretch = true;
    }
    stretches[position] = count;
  }
  return stretches;
}

}  // namespace

std::optional<PushPlanner::ThinWall> PushPlanner::thinWall(const Polygon& obstacle, double inflation,
                                                           double allowed_depth)
{
  if (obstacle.size() != 4) {
    return std::nullopt;
  }
  const Vector first = obstacle[1] - obstacle[0];
  const Vector second = obstacle[2] - obstacle[1];
  const bool rectangle = std::abs(first.dot(second)) <= 1e-9 * first.norm() * second.norm() &&
                         (obstacle[3] - obstacle[2] + first).norm() <= 1e-9 * first.norm();
  if (!rectangle) {
    return std::nullopt;
  }
  const bool first_shorter = first.norm() <= second.norm();
  const Vector& short_side = first_shorter ? first : second;
  const Vector& long_side = first_shorter ? second : first;
  const double half_width = short_side.norm() / 2.0;
  // The face ends where the inflation round its last cell begins.
  const double reach = long_side.norm() / 2.0 - inflation;
  if (half_width < inflation || half_width > allowed_depth || reach <= 0.0) {
    return std::nullopt;
  }
  ThinWall wall;
  wall.bounds = boundsOf(obstacle);
  wall.centre = (obstacle[0] + obstacle[2]) / 2.0;
  wall.across = short_side.normalized();
  wall.along = long_side.normalized();
  wall.reach = reach;
  return wall;
}

struct PushPlanner::Passage {
  Segment segment;
  Polygon window;  ///< the passage rectangle widened by the inflation, counter-clockwise
  /// Per raster cell: the outlet (1, 2, ...) it belongs to, 0 for none. An outlet is one stretch of
  /// the raster's edge where the start's or the goal's side of the unmoved object leaves the raster
  /// (none when the object separates nothing there).
  std::vector<int> outlets;
  int outlet_count = 0;  ///< every outlet must stay reachable from the start waypoint ...
  /// ... within this many raster steps (index: outlet): its steps from the start waypoint with the object
  /// gone plus onwardDetourSteps(); no bound where the object gone does not reach it either.
  std::vector<int> outlet_step_limits;
};

PushPlanner::PushPlanner(const PushProblemObject& problem, const PusherSettings& pusher,
                         const SearchSettings& search, const ConnectivitySettings& limits)
    : pusher_(pusher), search_(search)
{
  // Obstacles no push of this search comes near are left out: the scene may reach further, for a wider
  // search of the same object, and every collision test walks the list.
  Bounds reachable = boundsOf(problem.object);
  reachable.minimum -= Point::Constant(obstacleReach(limits, search, pusher));
  reachable.maximum += Point::Constant(obstacleReach(limits, search, pusher));
  for (const Polygon& obstacle : problem.obstacles) {
    const Bounds bounds = boundsOf(obstacle);
    if (bounds.overlaps(reachable)) {
      obstacles_.push_back(obstacle);
      obstacle_bounds_.push_back(bounds);
    }
  }
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
  double smallest_force = std::numeric_limits<double>::infinity();
  for (const EdgePushOptions& option : options_) {
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
  if (!std::isfinite(smallest_force)) {
    status_ = PlanStatus::NoStableContact;
    return;
  }
  heuristic_per_metre_ = smallest_force / search.reference_force_n;

  const std::vector<Point> footprint_samples = outlineSamples(model_.footprint, search.boundary_sample_m);
  collision_samples_ = {footprint_samples, footprint_samples};
  collision_outlines_ = {model_.footprint, model_.footprint};

  // A footprint recovered from a rasterised polygon may already sit a little inside a wall: allow what
  // the start pose has, so "never hit an obstacle" means "never pushed deeper".
  allowed_depth_m_ = pusher.inflation_m + search.penetration_tolerance_m;
  for (const Point& sample : footprint_samples) {
    const Point world = model_.pose.transform(sample);
    for (const Polygon& obstacle : obstacles_) {
      if (geometry::locatePoint(obstacle, world) == geometry::Containment::Inside) {
        allowed_depth_m_ = std::max(
            allowed_depth_m_, geometry::distanceToBoundary(obstacle, world) + search.penetration_tolerance_m);
      }
    }
  }

  if (!model_.depth_seen) {
    // The face is the footprint's longest edge; its ends lie on the line through the centroid.
    Vector along = Vector::UnitX();
    double longest = 0.0;
    for (std::size_t vertex = 0; vertex < model_.footprint.size(); ++vertex) {
      const Vector edge = model_.footprint[(vertex + 1) % model_.footprint.size()] - model_.footprint[vertex];
      if (edge.norm() > longest) {
        longest = edge.norm();
        along = edge / longest;
      }
    }
    double low = 0.0;
    double high = 0.0;
    for (const Point& vertex : model_.footprint) {
      low = std::min(low, vertex.dot(along));
      high = std::max(high, vertex.dot(along));
    }
    face_ends_ = {Point(along * low), Point(along * high)};
    face_normal_ = Vector(-along.y(), along.x());
    addUnseenDepth(search.unseen_depth_m, search.boundary_sample_m);
  }

  for (const Polygon& obstacle : obstacles_) {
    std::optional<ThinWall> wall = thinWall(obstacle, pusher.inflation_m, allowed_depth_m_);
    if (!wall) {
      continue;
    }
    // A point of the unmoved object already inside the wall's inflation is not held to its face, as the
    // depth test allows what the start pose has: the outlines are perceived (the demo room's doorway box
    // is 5 cm from each frame, its perceived footprint reaches past the west one).
    for (std::size_t side = 0; side < 2; ++side) {
      for (const Point& sample : collision_samples_[side]) {
        const Point world = model_.pose.transform(sample);
        wall->exempt[side].push_back(wall->bounds.contains(world) &&
                                     geometry::locatePoint(obstacle, world) == geometry::Containment::Inside);
      }
    }
    thin_walls_.push_back(std::move(*wall));
  }

  if (search.corridor) {
    // The corridor search judges the way on round each pushed pose instead (wayOnBeyond).
    junction_margin_m_ = surroundingsReach(limits, search) - search.search_radius_m;
  } else {
    Bounds surroundings = boundsOf(problem.object);
    const double reach = surroundingsReach(limits, search);
    surroundings.minimum -= Point::Constant(reach);
    surroundings.maximum += Point::Constant(reach);
    surroundings_.emplace(surroundings, kSurroundingsResolutionM);
    for (std::size_t index = 0; index < obstacles_.size(); ++index) {
      if (obstacle_bounds_[index].overlaps(surroundings)) {
        surroundings_->fill(obstacles_[index], FreeSpaceRaster::kObstacle);
      }
    }
  }

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
      samplePolyline(counter_clockwise, search.boundary_sample_m, switch_paths_[from][to][0].samples,
                     switch_paths_[from][to][0].length);
      samplePolyline(clockwise, search.boundary_sample_m, switch_paths_[from][to][1].samples,
                     switch_paths_[from][to][1].length);
    }
  }
}

Point PushPlanner::standingPoint(std::size_t edge) const
{
  const ContactPatch& patch = options_[edge].patch;
  return patch.middle - patch.push_direction * (pusher_.inflation_m + search_.contact_clearance_m);
}

Pose2 PushPlanner::vehiclePose(const Pose2& object_pose, std::size_t edge) const
{
  const ContactPatch& patch = options_[edge].patch;
  const Point axle = object_pose.transform(patch.middle - patch.push_direction * pusher_.bumper_to_axle_m);
  const Vector heading = rotate(patch.push_direction, object_pose.heading);
  return Pose2{axle.x(), axle.y(), std::atan2(heading.y(), heading.x())};
}

void PushPlanner::addUnseenDepth(double unseen_depth_m, double sample_spacing_m)
{
  double near = 0.0;
  double far = 0.0;
  for (const Point& vertex : model_.footprint) {
    near = std::min(near, vertex.dot(face_normal_));
    far = std::max(far, vertex.dot(face_normal_));
  }
  const double missing = unseen_depth_m - (far - near);
  if (!(missing > 0.0)) {
    return;
  }
  // Side 0 lies along face_normal_, side 1 against it. The depth stops where the object, standing where
  // it is, would enter a wall: it cannot be deeper than the room behind its face.
  const Vector along = (face_ends_[1] - face_ends_[0]).normalized();
  const double face_length = (face_ends_[1] - face_ends_[0]).norm();
  const int across = std::max(1, static_cast<int>(std::ceil(face_length / sample_spacing_m)));
  const int deep = std::max(1, static_cast<int>(std::ceil(missing / sample_spacing_m)));
  for (std::size_t side = 0; side < 2; ++side) {
    const Vector outward = side == 0 ? face_normal_ : Vector(-face_normal_);
    const Point base = face_ends_[0] + outward * (side == 0 ? far : -near);
    double reached = 0.0;
    for (int step = 1; step <= deep; ++step) {
      const double depth = missing * step / deep;
      bool enters_wall = false;
      for (int point = 0; point <= across && !enters_wall; ++point) {
        const Point body = base + along * (face_length * point / across) + outward * depth;
        const Point world = model_.pose.transform(body);
        enters_wall = insideDeeperThan(world, allowed_depth_m_);
      }
      if (enters_wall) {
        break;
      }
      reached = depth;
    }
    if (reached <= 0.0) {
      continue;
    }
    Polygon grown = model_.footprint;
    grown.push_back(base + outward * reached);
    grown.push_back(base + along * face_length + outward * reached);
    collision_outlines_[side] = geometry::convexHull(grown);
    collision_samples_[side] = outlineSamples(collision_outlines_[side], sample_spacing_m);
  }
}

bool PushPlanner::objectCollides(const Pose2& from, const Pose2& to, std::size_t side) const
{
  const Bounds after = boundsOf(transformed(collision_outlines_[side], to));
  for (std::size_t index = 0; index < obstacles_.size(); ++index) {
    if (!obstacle_bounds_[index].overlaps(after)) {
      continue;
    }
    for (const Point& sample : collision_samples_[side]) {
      const Point world = to.transform(sample);
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
  const Bounds before = boundsOf(transformed(collision_outlines_[side], from));
  const Bounds swept{before.minimum.cwiseMin(after.minimum), before.maximum.cwiseMax(after.maximum)};
  for (const ThinWall& wall : thin_walls_) {
    if (!wall.bounds.overlaps(swept)) {
      continue;
    }
    for (std::size_t index = 0; index < collision_samples_[side].size(); ++index) {
      if (wall.exempt[side][index]) {
        continue;
      }
      const Point start = from.transform(collision_samples_[side][index]);
      const Point end = to.transform(collision_samples_[side][index]);
      const double start_offset = (start - wall.centre).dot(wall.across);
      const double end_offset = (end - wall.centre).dot(wall.across);
      if (start_offset * end_offset >= 0.0) {
        continue;  // stays on one side of the face (or touches it)
      }
      const Point crossing = start + (end - start) * (start_offset / (start_offset - end_offset));
      if (std::abs((crossing - wall.centre).dot(wall.along)) <= wall.reach) {
        return true;
      }
    }
  }
  return false;
}

bool PushPlanner::turnConfined(const Pose2& pose, const Vector& depth_direction) const
{
  if (model_.depth_seen) {
    return false;
  }
  // A point of an inflated obstacle deeper than inflation - gap is closer than the gap to the wall.
  const double depth = pusher_.inflation_m - kConfinedFaceGapM;
  return std::all_of(face_ends_.begin(), face_ends_.end(), [&](const Point& end) {
    return insideDeeperThan(pose.transform(end), depth) &&
           insideDeeperThan(pose.transform(end + depth_direction * kConfinedFaceProbeM), depth);
  });
}

bool PushPlanner::insideDeeperThan(const Point& world, double depth) const
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

bool PushPlanner::pointBlocked(const Point& world) const
{
  return insideDeeperThan(world, -std::numeric_limits<double>::infinity());
}

bool PushPlanner::switchFree(const Pose2& pose, const SwitchPath& path) const
{
  return std::none_of(path.samples.begin(), path.samples.end(),
                      [&](const Point& sample) { return pointBlocked(pose.transform(sample)); });
}

double PushPlanner::heuristic(const Pose2& pose, const Passage& passage) const
{
  const Polygon inside = clipConvex(transformed(model_.footprint, pose), passage.window);
  if (inside.size() < 3) {
    return 0.0;
  }
  return geometry::width(inside) * heuristic_per_metre_;
}

double PushPlanner::objectClearance() const
{
  return pusher_.inflation_m + search_.passage_margin_m - search_.penetration_tolerance_m;
}

bool PushPlanner::passageClear(const Pose2& pose, const Passage& passage) const
{
  return segmentPolygonDistance(passage.segment, transformed(model_.footprint, pose)) >= objectClearance();
}

int PushPlanner::waypointSearchCells() const
{
  // A waypoint sits about the inflation from the object, so its cell may be covered: look that far.
  return static_cast<int>(std::ceil(pusher_.inflation_m / kSurroundingsResolutionM));
}

void PushPlanner::findOutlets(Passage& passage) const
{
  if (!surroundings_) {
    return;
  }
  FreeSpaceRaster unmoved = *surroundings_;
  unmoved.mark(unmoved.cellsNear(transformed(model_.footprint, model_.pose), objectClearance()),
               FreeSpaceRaster::kMovable);
  int components = 0;
  const std::vector<int> labels =
      unmoved.labelComponents(FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable, components);
  const auto start_cell = unmoved.nearestLabelled(passage.segment.start, labels, waypointSearchCells());
  const auto goal_cell = unmoved.nearestLabelled(passage.segment.end, labels, waypointSearchCells());
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
  const std::vector<int> stretches = ringStretches(ring, kept, passage.outlet_count);
  passage.outlets.assign(unmoved.cellCount(), 0);
  for (std::size_t position = 0; position < ring.size(); ++position) {
    passage.outlets[ring[position]] = stretches[position];
  }
  // How far each outlet is with the object gone: the pushed object may lengthen that by going round it.
  passage.outlet_step_limits.assign(static_cast<std::size_t>(passage.outlet_count) + 1,
                                    std::numeric_limits<int>::max());
  const auto open_start =
      surroundings_->nearestFree(passage.segment.start, FreeSpaceRaster::kObstacle, waypointSearchCells());
  if (!open_start) {
    return;
  }
  const int detour = onwardDetourSteps();
  int unmeasured = passage.outlet_count;
  surroundings_->searchFrom(*open_start, FreeSpaceRaster::kObstacle, [&](std::size_t cell, int steps) {
    const auto outlet = static_cast<std::size_t>(passage.outlets[cell]);
    if (outlet != 0 && passage.outlet_step_limits[outlet] == std::numeric_limits<int>::max()) {
      passage.outlet_step_limits[outlet] = steps + detour;
      --unmeasured;
    }
    return unmeasured == 0;
  });
}

int PushPlanner::onwardDetourSteps() const
{
  double reach = 0.0;
  for (const Point& vertex : model_.footprint) {
    reach = std::max(reach, vertex.norm());
  }
  // Half way round the object's disc grown by the clearance, in 4-neighbour steps (up to sqrt(2) times
  // the straight length), plus the slack.
  const double detour_m = geometry::kPi * (reach + objectClearance()) + kOnwardDetourSlackM;
  return static_cast<int>(std::ceil(std::sqrt(2.0) * detour_m / kSurroundingsResolutionM));
}

bool PushPlanner::onwardOpen(const Pose2& pose, const Passage& passage) const
{
  if (!surroundings_ || passage.outlet_count == 0) {
    return true;
  }
  const Polygon footprint = transformed(model_.footprint, pose);
  // An object with a free cell between it and every obstacle (and the raster's edge) is an island: it
  // cannot cut free space apart.
  const std::vector<FreeSpaceRaster::CellDistance> neighbourhood =
      surroundings_->cellDistancesNear(footprint, objectClearance() + 1.5 * kSurroundingsResolutionM);
  if (std::none_of(neighbourhood.begin(), neighbourhood.end(),
                   [&](const FreeSpaceRaster::CellDistance& near) {
                     return (surroundings_->layers(near.cell) & FreeSpaceRaster::kObstacle) != 0 ||
                            surroundings_->onBorder(near.cell);
                   })) {
    return true;
  }
  FreeSpaceRaster moved = *surroundings_;
  std::vector<std::size_t> covered;
  for (const FreeSpaceRaster::CellDistance& near : neighbourhood) {
    if (near.distance_m <= objectClearance()) {
      covered.push_back(near.cell);
    }
  }
  moved.mark(covered, FreeSpaceRaster::kMovable);
  const std::uint8_t blocked = FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable;
  const auto start_cell = moved.nearestFree(passage.segment.start, blocked, waypointSearchCells());
  if (!start_cell) {
    return false;
  }
  std::vector<bool> reached(static_cast<std::size_t>(passage.outlet_count) + 1, false);
  int missing = passage.outlet_count;
  bool too_far = false;
  // Nearest first: an outlet's first cell is as near as it gets.
  moved.searchFrom(*start_cell, blocked, [&](std::size_t cell, int steps) {
    const auto outlet = static_cast<std::size_t>(passage.outlets[cell]);
    if (outlet != 0 && !reached[outlet]) {
      if (steps > passage.outlet_step_limits[outlet]) {
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

bool PushPlanner::goalReached(const Pose2& pose, const Passage& passage) const
{
  return passageClear(pose, passage) && onwardOpen(pose, passage);
}

PushControl PushPlanner::makeControl(ControlKind kind, std::size_t edge, double distance, double radius,
                                     double force, const Pose2& end_pose) const
{
  PushControl control;
  control.kind = kind;
  control.contact_edge = edge;
  control.distance_m = distance;
  control.force_n = force;
  control.object_pose = end_pose;
  control.vehicle_pose = vehiclePose(end_pose, edge);
  if (kind == ControlKind::ContactSwitch) {
    control.duration_s = distance / search_.travel_speed_mps;
  } else {
    control.linear_mps = search_.push_speed_mps;
    control.angular_radps = std::isfinite(radius) ? search_.push_speed_mps / radius : 0.0;
    control.duration_s = distance / search_.push_speed_mps;
  }
  return control;
}

void PushPlanner::completePlan(PushPlan& plan, std::size_t edge, double approach_m,
                               std::vector<PushControl> controls) const
{
  plan.status = PlanStatus::Found;
  plan.contact_edge = edge;
  plan.contact_pose = vehiclePose(model_.pose, edge);
  plan.travel_distance_m = approach_m;
  plan.approach_distance_m = approach_m;
  plan.push_distance_m = 0.0;
  plan.push_work_nm = 0.0;
  plan.expected_force_n = 0.0;
  for (const PushControl& control : controls) {
    if (control.kind == ControlKind::ContactSwitch) {
      plan.travel_distance_m += control.distance_m;
    } else {
      plan.push_distance_m += control.distance_m;
      plan.push_work_nm += control.force_n * control.distance_m;
      plan.expected_force_n = std::max(plan.expected_force_n, control.force_n);
    }
  }
  plan.controls = std::move(controls);
  plan.cost = plan.push_work_nm / search_.reference_force_n + plan.travel_distance_m;
}

std::vector<PushPlanner::Contact> PushPlanner::reachableContacts(const Point& start) const
{
  std::vector<Contact> contacts;
  const Polygon outline_world = transformed(model_.travel_outline, model_.pose);
  for (std::size_t edge = 0; edge < options_.size(); ++edge) {
    if (!options_[edge].pushable()) {
      continue;
    }
    const Point standing = model_.pose.transform(standingPoint(edge));
    if (pointBlocked(standing)) {
      continue;
    }
    const Segment approach{start, standing};
    bool visible = true;
    for (std::size_t index = 0; index < outline_world.size() && visible; ++index) {
      visible = !geometry::segmentsCrossProperly(approach, geometry::polygonEdge(outline_world, index));
    }
    for (std::size_t index = 0; index < obstacles_.size() && visible; ++index) {
      for (std::size_t side = 0; side < obstacles_[index].size() && visible; ++side) {
        visible = !geometry::segmentsCrossProperly(approach, geometry::polygonEdge(obstacles_[index], side));
      }
    }
    if (visible) {
      contacts.push_back(Contact{edge, approach.length()});
    }
  }
  return contacts;
}

bool PushPlanner::wayOnBeyond(const Pose2& pose, std::size_t edge) const
{
  const Polygon footprint = transformed(model_.footprint, pose);
  Bounds window = boundsOf(footprint);
  window.minimum -= Point::Constant(junction_margin_m_);
  window.maximum += Point::Constant(junction_margin_m_);
  FreeSpaceRaster raster(window, kSurroundingsResolutionM);
  for (std::size_t index = 0; index < obstacles_.size(); ++index) {
    if (obstacle_bounds_[index].overlaps(window)) {
      raster.fill(obstacles_[index], FreeSpaceRaster::kObstacle);
    }
  }
  raster.mark(raster.cellsNear(footprint, objectClearance()), FreeSpaceRaster::kMovable);
  int components = 0;
  const std::vector<int> labels =
      raster.labelComponents(FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable, components);
  const auto behind =
      raster.nearestLabelled(pose.transform(standingPoint(edge)), labels, waypointSearchCells());
  const std::vector<std::size_t> ring = raster.borderCells();
  if (!behind || ring.empty()) {
    return false;
  }
  const auto reached = [&](std::size_t cell) { return labels[cell] == labels[*behind]; };
  if (std::all_of(ring.begin(), ring.end(), reached)) {
    return true;  // the object stands in open space
  }
  int stretches = 0;
  ringStretches(ring, reached, stretches);
  return stretches >= 2;
}

PushPlan PushPlanner::corridorPush(PushPlan plan, const std::vector<Contact>& contacts,
                                   const Passage& passage, std::size_t depth_side) const
{
  const auto started = std::chrono::steady_clock::now();
  plan.status = PlanStatus::Exhausted;
  std::size_t checked = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Contact& contact : contacts) {
    const EdgePushOptions& option = options_[contact.edge];
    if (!option.straight) {
      continue;
    }
    const Vector direction = rotate(option.patch.push_direction, model_.pose.heading);
    const auto poseAt = [&](int step) {
      const double distance = step * search_.collision_step_m;
      return Pose2{model_.pose.x + direction.x() * distance, model_.pose.y + direction.y() * distance,
                   model_.pose.heading};
    };
    const auto opens = [&](int step) {
      const Pose2 pose = poseAt(step);
      if (!passageClear(pose, passage)) {
        return false;
      }
      ++checked;
      return wayOnBeyond(pose, contact.edge);
    };
    const int steps = static_cast<int>(std::floor(search_.search_radius_m / search_.collision_step_m));
    int last = 0;  // the farthest step before the object runs into an obstacle
    while (last < steps && !objectCollides(poseAt(last), poseAt(last + 1), depth_side)) {
      ++last;
    }
    // The way on is judged every kCorridorJudgementStepM, then refined back to the first collision step
    // it holds at: each judgement rasterises the object's surroundings, and once the object is past a
    // side opening the vehicle behind it keeps reaching that opening, so no open stretch is skipped.
    const int stride =
        std::max(1, static_cast<int>(std::lround(kCorridorJudgementStepM / search_.collision_step_m)));
    int first_open = 0;
    for (int probe = stride; first_open == 0 && probe < last + stride; probe += stride) {
      const int step = std::min(probe, last);
      if (opens(step)) {
        first_open = step;
        while (first_open > 1 && first_open > step - stride + 1 && opens(first_open - 1)) {
          --first_open;
        }
      }
    }
    if (first_open > 0) {
      const double distance = first_open * search_.collision_step_m;
      const double cost = contact.approach_m + option.straight_force_n * distance / search_.reference_force_n;
      if (cost >= best_cost) {
        continue;
      }
      best_cost = cost;
      completePlan(
          plan, contact.edge, contact.approach_m,
          {makeControl(ControlKind::Straight, contact.edge, distance, std::numeric_limits<double>::infinity(),
                       option.straight_force_n, poseAt(first_open))});
    }
  }
  plan.expansions = checked;
  plan.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return plan;
}

PushPlan PushPlanner::plan(const Point& start, const Point& goal) const
{
  const auto started = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  PushPlan plan;
  plan.status = status_;
  plan.footprint = model_.footprint;
  plan.start_object_pose = model_.pose;
  if (status_ != PlanStatus::Found) {
    return plan;
  }
  if (!start.allFinite() || !goal.allFinite() || (goal - start).norm() < 1e-6 || pointBlocked(start) ||
      pointBlocked(goal)) {
    plan.status = PlanStatus::InvalidWaypoints;
    return plan;
  }

  Passage passage;
  passage.segment = Segment{start, goal};
  const Vector along = (goal - start).normalized();
  const Vector across(-along.y(), along.x());
  const double half = pusher_.inflation_m;
  passage.window = {start - along * half - across * half, goal + along * half - across * half,
                    goal + along * half + across * half, start - along * half + across * half};
  findOutlets(passage);

  const std::size_t bins = std::max<std::size_t>(1, search_.heading_bins);
  const auto key = [&](const Pose2& pose, std::size_t edge) {
    const auto cell = [&](double value) {
      return static_cast<std::uint64_t>(
          static_cast<std::int64_t>(std::floor(value / search_.position_resolution_m)) & 0xFFFFF);
    };
    const double turn = (geometry::wrapAngle(pose.heading) + geometry::kPi) / (2.0 * geometry::kPi);
    const auto heading_cell = static_cast<std::uint64_t>(
        std::min(bins - 1, static_cast<std::size_t>(turn * static_cast<double>(bins))));
    return (cell(pose.x) << 44) | (cell(pose.y) << 24) | (heading_cell << 8) |
           static_cast<std::uint64_t>(edge & 0xFF);
  };

  std::vector<Node> nodes;
  std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>> open;
  std::unordered_map<std::uint64_t, double> best_cost;

  // An object seen only as a face: its depth lies beyond the face as seen from where the push starts.
  const bool depth_along_normal = face_normal_.dot(model_.pose.position() - start) >= 0.0;
  const Vector depth_direction = depth_along_normal ? face_normal_ : Vector(-face_normal_);
  const std::size_t depth_side = depth_along_normal ? 0 : 1;

  const std::vector<Contact> contacts = reachableContacts(start);
  if (contacts.empty()) {
    plan.status = PlanStatus::UnreachableContact;
    return plan;
  }
  if (search_.corridor) {
    return corridorPush(std::move(plan), contacts, passage, depth_side);
  }
  for (const Contact& contact : contacts) {
    Node root;
    root.pose = model_.pose;
    root.edge = contact.edge;
    root.approach_m = contact.approach_m;
    root.cost = root.approach_m;
    root.root = true;
    nodes.push_back(root);
    open.push(QueueEntry{root.cost + heuristic(root.pose, passage), static_cast<int>(nodes.size() - 1)});
  }

  int goal_node = -1;
  const auto straightPose = [&](const Pose2& pose, std::size_t edge, double distance) {
    const Vector direction = rotate(options_[edge].patch.push_direction, pose.heading);
    return Pose2{pose.x + direction.x() * distance, pose.y + direction.y() * distance, pose.heading};
  };
  const auto arcPose = [&](const Pose2& pose, std::size_t edge, double radius, double distance) {
    // radius > 0 turns left; the rotation centre is on the vehicle's axle line.
    const Pose2 vehicle = vehiclePose(pose, edge);
    const Vector left(-std::sin(vehicle.heading), std::cos(vehicle.heading));
    const Point centre = vehicle.position() + left * radius;
    return rotateAbout(pose, centre, distance / radius);
  };
  // An object pose no push may reach: in an obstacle, or beyond the search radius, where the object would
  // leave the surroundings the onward check sees (a box pushed on along a corridor would look as if it had
  // left the corridor).
  const auto ruledOut = [&](const Pose2& from, const Pose2& to) {
    return (to.position() - model_.pose.position()).norm() > search_.search_radius_m ||
           objectCollides(from, to, depth_side);
  };
  const auto pushAllowed = [&](const std::function<Pose2(double)>& along_motion, double distance) {
    const int steps = std::max(1, static_cast<int>(std::ceil(distance / search_.collision_step_m)));
    Pose2 previous = along_motion(0.0);
    for (int step = 1; step <= steps; ++step) {
      const Pose2 next = along_motion(distance * step / steps);
      if (ruledOut(previous, next)) {
        return false;
      }
      previous = next;
    }
    return true;
  };
  const auto addNode = [&](int parent_index, const Pose2& pose, std::size_t edge, double cost,
                           const PushControl& control) {
    const std::uint64_t state = key(pose, edge);
    const auto found = best_cost.find(state);
    if (found != best_cost.end() && found->second <= cost + 1e-9) {
      return;
    }
    best_cost[state] = cost;
    Node node;
    node.pose = pose;
    node.edge = edge;
    node.cost = cost;
    node.parent = parent_index;
    node.control = control;
    nodes.push_back(node);
    open.push(QueueEntry{cost + heuristic(pose, passage), static_cast<int>(nodes.size() - 1)});
  };

  std::size_t expansions = 0;
  PlanStatus outcome = PlanStatus::Exhausted;
  while (!open.empty()) {
    if (expansions >= search_.max_expansions) {
      outcome = PlanStatus::ExpansionLimit;
      break;
    }
    if ((expansions & 15U) == 0 && elapsed() > search_.time_budget_s) {
      outcome = PlanStatus::TimeBudget;
      break;
    }
    const int current_index = open.top().node;
    open.pop();
    const Node current = nodes[static_cast<std::size_t>(current_index)];
    const auto settled = best_cost.find(key(current.pose, current.edge));
    if (!current.root && settled != best_cost.end() && settled->second < current.cost - 1e-9) {
      continue;  // a cheaper copy of this state was queued later
    }
    if (goalReached(current.pose, passage)) {
      goal_node = current_index;
      break;
    }
    ++expansions;
    const EdgePushOptions& option = options_[current.edge];

    // Analytic expansion: one straight push to the goal when nothing is in the way.
    if (option.straight &&
        (current.root || expansions % std::max<std::size_t>(1, search_.analytic_interval) == 0)) {
      const int steps =
          static_cast<int>(std::ceil(search_.analytic_max_distance_m / search_.collision_step_m));
      Pose2 previous = current.pose;
      for (int step = 1; step <= steps; ++step) {
        const double distance = step * search_.collision_step_m;
        const Pose2 pose = straightPose(current.pose, current.edge, distance);
        if (ruledOut(previous, pose)) {
          break;
        }
        previous = pose;
        if (goalReached(pose, passage)) {
          Node node;
          node.pose = pose;
          node.edge = current.edge;
          node.cost = current.cost + option.straight_force_n * distance / search_.reference_force_n;
          node.parent = current_index;
          node.control = makeControl(ControlKind::Straight, current.edge, distance,
                                     std::numeric_limits<double>::infinity(), option.straight_force_n, pose);
          nodes.push_back(node);
          goal_node = static_cast<int>(nodes.size() - 1);
          break;
        }
      }
      if (goal_node >= 0) {
        break;
      }
    }

    const double length = search_.primitive_length_m;
    if (option.straight) {
      const auto motion = [&](double distance) { return straightPose(current.pose, current.edge, distance); };
      if (pushAllowed(motion, length)) {
        const Pose2 pose = motion(length);
        addNode(current_index, pose, current.edge,
                current.cost + option.straight_force_n * length / search_.reference_force_n,
                makeControl(ControlKind::Straight, current.edge, length,
                            std::numeric_limits<double>::infinity(), option.straight_force_n, pose));
      }
    }
    const std::array<std::pair<double, double>, 2> arcs{
        std::make_pair(option.left_radius_m, option.left_force_n),
        std::make_pair(-option.right_radius_m, option.right_force_n)};
    const bool may_turn = !turnConfined(current.pose, depth_direction);
    for (const auto& [radius, force] : arcs) {
      if (!may_turn || !std::isfinite(radius)) {
        continue;
      }
      const auto motion = [&, radius = radius](double distance) {
        return arcPose(current.pose, current.edge, radius, distance);
      };
      if (pushAllowed(motion, length)) {
        const Pose2 pose = motion(length);
        addNode(current_index, pose, current.edge, current.cost + force * length / search_.reference_force_n,
                makeControl(radius > 0.0 ? ControlKind::ArcLeft : ControlKind::ArcRight, current.edge, length,
                            radius, force, pose));
      }
    }
    if (current.control.kind != ControlKind::ContactSwitch || current.root) {
      for (std::size_t edge = 0; edge < options_.size(); ++edge) {
        if (edge == current.edge || !options_[edge].pushable()) {
          continue;
        }
        const auto& paths = switch_paths_[current.edge][edge];
        const std::size_t shorter = paths[0].length <= paths[1].length ? 0 : 1;
        for (const std::size_t direction : {shorter, 1 - shorter}) {
          if (switchFree(current.pose, paths[direction])) {
            addNode(current_index, current.pose, edge, current.cost + paths[direction].length,
                    makeControl(ControlKind::ContactSwitch, edge, paths[direction].length, 0.0, 0.0,
                                current.pose));
            break;
          }
        }
      }
    }
  }

  plan.expansions = expansions;
  plan.planning_time_s = elapsed();
  if (goal_node < 0) {
    plan.status = outcome;
    return plan;
  }
  std::vector<int> chain;
  for (int index = goal_node; index >= 0; index = nodes[static_cast<std::size_t>(index)].parent) {
    chain.push_back(index);
  }
  std::reverse(chain.begin(), chain.end());
  const Node& root = nodes[static_cast<std::size_t>(chain.front())];
  std::vector<PushControl> controls;
  for (std::size_t link = 1; link < chain.size(); ++link) {
    controls.push_back(nodes[static_cast<std::size_t>(chain[link])].control);
  }
  completePlan(plan, root.edge, root.approach_m, std::move(controls));
  return plan;
}

}  // namespace ifar::interaction
