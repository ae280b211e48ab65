#include "planner/interaction/connectivity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/free_space_raster.hpp"
#include "planner/interaction/object_model.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Segment;
using geometry::Vector;

namespace {

constexpr double kSameParameter = 1e-7;

/// Distance along the ray origin + t * direction (unit) to the segment, if it hits it at t > 0.
std::optional<double> rayHit(const Point& origin, const Vector& direction, const Segment& segment)
{
  const Vector edge = segment.end - segment.start;
  const double denominator = geometry::cross(direction, edge);
  if (std::abs(denominator) < 1e-12) {
    return std::nullopt;
  }
  const Vector offset = segment.start - origin;
  const double t = geometry::cross(offset, edge) / denominator;
  const double u = geometry::cross(offset, direction) / denominator;
  if (t <= 1e-9 || u < -1e-12 || u > 1.0 + 1e-12) {
    return std::nullopt;
  }
  return t;
}

/// Arc-length position along the polygon boundary.
struct Boundary {
  const Polygon& polygon;
  std::vector<double> starts;  ///< arc length where edge i begins
  double perimeter = 0.0;

  explicit Boundary(const Polygon& outline) : polygon(outline)
  {
    for (std::size_t index = 0; index < outline.size(); ++index) {
      starts.push_back(perimeter);
      perimeter += geometry::polygonEdge(outline, index).length();
    }
  }

  Point at(double arc) const
  {
    arc = std::fmod(arc, perimeter);
    if (arc < 0.0) {
      arc += perimeter;
    }
    const auto upper = std::upper_bound(starts.begin(), starts.end(), arc);
    const std::size_t edge = static_cast<std::size_t>(std::distance(starts.begin(), upper)) - 1;
    const Segment segment = geometry::polygonEdge(polygon, edge);
    const double length = segment.length();
    return length > 0.0
               ? Point(segment.start + (segment.end - segment.start) * ((arc - starts[edge]) / length))
               : segment.start;
  }
};

/// Arc-length positions where the movable boundary meets an obstacle boundary, sorted, unique.
std::vector<double> boundaryIntersections(const Boundary& boundary, const std::vector<Polygon>& obstacles)
{
  std::vector<double> arcs;
  const Bounds movable_bounds = boundsOf(boundary.polygon);
  const auto add_on_edge = [&](std::size_t edge, const Point& point) {
    const Segment segment = geometry::polygonEdge(boundary.polygon, edge);
    if (geometry::distanceToSegment(point, segment) <= 1e-9) {
      arcs.push_back(boundary.starts[edge] + (point - segment.start).norm());
    }
  };
  for (const Polygon& obstacle : obstacles) {
    if (!boundsOf(obstacle).overlaps(movable_bounds)) {
      continue;
    }
    for (std::size_t edge = 0; edge < boundary.polygon.size(); ++edge) {
      const Segment segment = geometry::polygonEdge(boundary.polygon, edge);
      for (std::size_t other = 0; other < obstacle.size(); ++other) {
        const Segment obstacle_edge = geometry::polygonEdge(obstacle, other);
        if (!geometry::segmentsIntersect(segment, obstacle_edge)) {
          continue;
        }
        if (const auto point = geometry::segmentIntersectionPoint(segment, obstacle_edge)) {
          add_on_edge(edge, *point);
        } else {  // collinear overlap: its ends
          add_on_edge(edge, obstacle_edge.start);
          add_on_edge(edge, obstacle_edge.end);
          if (geometry::distanceToSegment(segment.start, obstacle_edge) <= 1e-9) {
            add_on_edge(edge, segment.start);
          }
          if (geometry::distanceToSegment(segment.end, obstacle_edge) <= 1e-9) {
            add_on_edge(edge, segment.end);
          }
        }
      }
    }
  }
  std::sort(arcs.begin(), arcs.end());
  arcs.erase(std::unique(arcs.begin(), arcs.end(),
                         [](double first, double second) { return second - first < kSameParameter; }),
             arcs.end());
  if (arcs.size() > 1 && arcs.back() - arcs.front() > boundary.perimeter - kSameParameter) {
    arcs.pop_back();  // the same point seen from both ends of the loop
  }
  return arcs;
}

struct Candidate {
  TopologicalWaypoint waypoint;
  double stretch_length = 0.0;
  double arc = 0.0;
};

bool isFree(const Point& point, const std::vector<Polygon>& obstacles)
{
  return std::none_of(obstacles.begin(), obstacles.end(), [&](const Polygon& obstacle) {
    return geometry::locatePoint(obstacle, point) != geometry::Containment::Outside;
  });
}

/// Eq. 1 for the free stretch between two consecutive intersection points.
std::optional<Candidate> placeWaypoint(const Boundary& boundary, double start_arc, double end_arc,
                                       const std::vector<Polygon>& obstacles,
                                       const ConnectivitySettings& settings)
{
  const Point first = boundary.at(start_arc);
  const Point second = boundary.at(end_arc);
  const Vector chord = second - first;
  if (chord.norm() < 1e-6) {
    return std::nullopt;
  }
  // chord x (0, 0, 1): to the right of the chord, where the counter-clockwise stretch bulges out.
  const Vector normal = Vector(chord.y(), -chord.x()).normalized();
  const Point middle = (first + second) / 2.0;
  double exit = -1.0;
  for (std::size_t edge = 0; edge < boundary.polygon.size(); ++edge) {
    if (const auto hit = rayHit(middle, normal, geometry::polygonEdge(boundary.polygon, edge))) {
      exit = std::max(exit, *hit);
    }
  }
  const Point boundary_point =
      exit >= 0.0 ? Point(middle + normal * exit) : boundary.at((start_arc + end_arc) / 2.0);
  double obstacle_distance = settings.window_margin_m;
  for (const Polygon& obstacle : obstacles) {
    for (std::size_t edge = 0; edge < obstacle.size(); ++edge) {
      if (const auto hit = rayHit(boundary_point, normal, geometry::polygonEdge(obstacle, edge))) {
        obstacle_distance = std::min(obstacle_distance, *hit);
      }
    }
  }
  Candidate candidate;
  candidate.waypoint.boundary_point = boundary_point;
  candidate.waypoint.normal = normal;
  candidate.waypoint.position =
      boundary_point + normal * std::min(settings.waypoint_offset_m, obstacle_distance / 2.0);
  candidate.stretch_length = end_arc - start_arc;
  candidate.arc = start_arc;
  return candidate;
}

}  // namespace

std::vector<Polygon> obstaclesFor(const LocalScene& scene, std::size_t movable_index,
                                  const ConnectivitySettings& settings, std::size_t& skipped)
{
  std::vector<Polygon> obstacles;
  const auto take = [&](const Polygon& polygon) {
    if (checkPolygon(polygon, settings) == PlanStatus::DegeneratePolygon) {
      ++skipped;
    } else {
      obstacles.push_back(polygon);  // large background polygons are fine as obstacles
    }
  };
  for (const Polygon& polygon : scene.background) {
    take(polygon);
  }
  for (std::size_t index = 0; index < scene.movable.size(); ++index) {
    if (index != movable_index) {
      take(scene.movable[index]);
    }
  }
  return obstacles;
}

ConnectivityResult analyzeConnectivity(const LocalScene& scene, std::size_t movable_index,
                                       const ConnectivitySettings& settings)
{
  ConnectivityResult result;
  if (movable_index >= scene.movable.size()) {
    result.status = PlanStatus::DegeneratePolygon;
    return result;
  }
  result.status = checkPolygon(scene.movable[movable_index], settings);
  if (result.status != PlanStatus::Found) {
    return result;
  }
  const Polygon movable = geometry::counterClockwise(scene.movable[movable_index]);
  const std::vector<Polygon> obstacles =
      obstaclesFor(scene, movable_index, settings, result.skipped_polygons);

  const Boundary boundary(movable);
  const std::vector<double> arcs = boundaryIntersections(boundary, obstacles);
  if (arcs.size() < 2) {
    return result;  // free-standing or touching at one point: it cannot split anything
  }
  std::vector<Candidate> candidates;
  for (std::size_t index = 0; index < arcs.size(); ++index) {
    const double start_arc = arcs[index];
    const double end_arc = index + 1 < arcs.size() ? arcs[index + 1] : arcs.front() + boundary.perimeter;
    if (end_arc - start_arc < settings.minimum_stretch_m ||
        !isFree(boundary.at((start_arc + end_arc) / 2.0), obstacles)) {
      continue;
    }
    if (auto candidate = placeWaypoint(boundary, start_arc, end_arc, obstacles, settings)) {
      candidates.push_back(*candidate);
    }
  }
  if (candidates.size() < 2) {
    return result;
  }

  Bounds window = boundsOf(movable);
  window.minimum -= Point::Constant(settings.window_margin_m);
  window.maximum += Point::Constant(settings.window_margin_m);
  FreeSpaceRaster raster(window, settings.raster_resolution_m);
  for (const Polygon& obstacle : obstacles) {
    if (boundsOf(obstacle).overlaps(window)) {
      raster.fill(obstacle, FreeSpaceRaster::kObstacle);
    }
  }
  raster.fill(movable, FreeSpaceRaster::kMovable);
  int with_object_count = 0;
  int without_object_count = 0;
  const std::vector<int> with_object =
      raster.labelComponents(FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable, with_object_count);
  const std::vector<int> without_object =
      raster.labelComponents(FreeSpaceRaster::kObstacle, without_object_count);

  // Best candidate per component (longest free stretch), then keep components that merge without it.
  std::map<int, Candidate> best;
  std::map<int, int> merged_of;
  for (const Candidate& candidate : candidates) {
    const auto cell = raster.nearestLabelled(candidate.waypoint.position, with_object, 3);
    if (!cell) {
      continue;
    }
    const int component = with_object[*cell];
    merged_of[component] = without_object[*cell];
    auto found = best.find(component);
    if (found == best.end() || candidate.stretch_length > found->second.stretch_length) {
      best[component] = candidate;
    }
  }
  std::map<int, int> members;
  for (const auto& entry : merged_of) {
    ++members[entry.second];
  }
  std::vector<Candidate> kept;
  for (const auto& entry : best) {
    if (members[merged_of[entry.first]] >= 2) {
      kept.push_back(entry.second);
    }
  }
  if (kept.size() < 2) {
    return result;
  }
  std::sort(kept.begin(), kept.end(), [](const Candidate& a, const Candidate& b) { return a.arc < b.arc; });
  result.splits = true;
  for (std::size_t index = 0; index < kept.size(); ++index) {
    kept[index].waypoint.component = index;
    result.waypoints.push_back(kept[index].waypoint);
  }
  for (std::size_t from = 0; from < kept.size(); ++from) {
    for (std::size_t to = 0; to < kept.size(); ++to) {
      if (from != to) {
        result.pairs.push_back(OrderedPair{from, to});
      }
    }
  }
  return result;
}

}  // namespace ifar::interaction
