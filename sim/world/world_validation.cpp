#include "sim/world/world_validation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include <Eigen/Geometry>

#include "common/geometry/box_sweep.hpp"

#include "sim/world/world_geometry.hpp"

namespace ifar::sim {
namespace {

std::string obstacleEntity(const StaticObstacle& obstacle)
{
  return "obstacle '" + obstacle.name + "'";
}

std::string objectEntity(const MovableObject& object)
{
  return "object '" + object.name + "' (id " + std::to_string(object.id) + ")";
}

bool finite(const geometry::Point& point)
{
  return std::isfinite(point.x()) && std::isfinite(point.y());
}

/// Far beyond any site a vehicle works in; the physics' single-precision bodies lose their millimetres
/// past it, and an outline spanning a billion metres is a typo, not a wall.
constexpr double kMaxCoordinateM = 1e5;
/// Ten turns either way: a heading written in degrees past this is a typo (or hostile), not a pose.
constexpr double kMaxHeadingRad = 20.0 * 3.14159265358979323846;

bool withinExtent(const geometry::Point& point)
{
  return std::abs(point.x()) <= kMaxCoordinateM && std::abs(point.y()) <= kMaxCoordinateM;
}

/// What is wrong with a pose (empty when nothing): not finite, beyond the extent, or a heading of many turns.
std::optional<std::string> poseProblem(const geometry::Pose2& pose)
{
  if (!finite(pose.position()) || !std::isfinite(pose.heading)) {
    return std::string("pose is not finite");
  }
  if (!withinExtent(pose.position())) {
    return "pose lies beyond " + std::to_string(static_cast<int>(kMaxCoordinateM)) + " m of the origin";
  }
  if (std::abs(pose.heading) > kMaxHeadingRad) {
    return std::string("heading is more than ten turns (3600 degrees) either way");
  }
  return std::nullopt;
}

void checkObject(const MovableObject& object, std::vector<WorldProblem>& problems)
{
  const auto entity = objectEntity(object);
  if (object.id <= 0) {
    problems.push_back({entity, "id must be positive"});
  }
  if (!(object.mass_kg > 0.0) || !std::isfinite(object.mass_kg)) {
    problems.push_back({entity, "mass must be positive, got " + std::to_string(object.mass_kg) + " kg"});
  }
  if (!(object.height_m > 0.0) || !std::isfinite(object.height_m)) {
    problems.push_back({entity, "height must be positive, got " + std::to_string(object.height_m) + " m"});
  }
  if (!(object.ground_friction >= 0.0) || !std::isfinite(object.ground_friction)) {
    problems.push_back(
        {entity, "ground friction must be >= 0, got " + std::to_string(object.ground_friction)});
  }
  if (!(object.reflectivity >= 0.0 && object.reflectivity <= 1.0)) {
    problems.push_back(
        {entity, "reflectivity must be within 0..1, got " + std::to_string(object.reflectivity)});
  }
  if (const auto problem = poseProblem(object.pose)) {
    problems.push_back({entity, *problem});
  }
  if (const auto problem = polygonProblem(object.outline)) {
    problems.push_back({entity, *problem});
  }
}

void checkObstacle(const StaticObstacle& obstacle, std::vector<WorldProblem>& problems)
{
  const auto entity = obstacleEntity(obstacle);
  if (!(obstacle.height_m > 0.0) || !std::isfinite(obstacle.height_m)) {
    problems.push_back({entity, "height must be positive, got " + std::to_string(obstacle.height_m) + " m"});
  }
  if (!(obstacle.reflectivity >= 0.0 && obstacle.reflectivity <= 1.0)) {
    problems.push_back(
        {entity, "reflectivity must be within 0..1, got " + std::to_string(obstacle.reflectivity)});
  }
  if (const auto problem = polygonProblem(obstacle.outline)) {
    problems.push_back({entity, *problem});
  }
}

}  // namespace

std::optional<std::string> polygonProblem(const geometry::Polygon& polygon)
{
  for (const auto& vertex : polygon) {
    if (!finite(vertex)) {
      return std::string("polygon has a non-finite coordinate");
    }
    if (!withinExtent(vertex)) {
      return "polygon reaches beyond " + std::to_string(static_cast<int>(kMaxCoordinateM)) +
             " m of the origin";
    }
  }
  if (polygon.size() < 3) {
    return "open or degenerate polygon: " + std::to_string(polygon.size()) + " vertices, at least 3 needed";
  }
  for (std::size_t index = 0; index < polygon.size(); ++index) {
    const auto& next = polygon[(index + 1) % polygon.size()];
    if ((polygon[index] - next).norm() <= geometry::kEpsilon) {
      return "degenerate polygon: vertex " + std::to_string(index) + " repeats the next one";
    }
  }
  if (geometry::area(polygon) <= geometry::kEpsilon) {
    return std::string("degenerate polygon: zero area");
  }
  if (!geometry::isSimple(polygon)) {
    return std::string("self-intersecting polygon");
  }
  return std::nullopt;
}

std::vector<WorldProblem> findWorldProblems(const World& world)
{
  std::vector<WorldProblem> problems;
  for (const auto& obstacle : world.obstacles) {
    checkObstacle(obstacle, problems);
  }
  std::map<std::int64_t, std::string> ids;
  for (const auto& object : world.objects) {
    checkObject(object, problems);
    const auto [found, inserted] = ids.emplace(object.id, object.name);
    if (!inserted) {
      problems.push_back({objectEntity(object), "id is already used by object '" + found->second + "'"});
    }
  }
  if (!problems.empty()) {
    return problems;  // overlap tests need valid polygons
  }

  std::vector<geometry::Polygon> placed;
  placed.reserve(world.objects.size());
  for (const auto& object : world.objects) {
    placed.push_back(placedOutline(object));
  }
  // Objects first, then obstacles: only pairs whose boxes meet are tested, in the order of the objects
  // and, for each, its obstacles before the objects after it.
  std::vector<Eigen::AlignedBox2d> boxes;
  boxes.reserve(placed.size() + world.obstacles.size());
  for (const geometry::Polygon& outline : placed) {
    boxes.push_back(geometry::boundingBox(outline));
  }
  for (const auto& obstacle : world.obstacles) {
    boxes.push_back(geometry::boundingBox(obstacle.outline));
  }
  const std::size_t objects = placed.size();
  std::vector<std::pair<std::size_t, std::size_t>> candidates;  // (object, other: obstacles after objects)
  for (const auto& [first, second] : geometry::overlappingBoxPairs(
           common::Span<const Eigen::AlignedBox2d>(boxes.data(), boxes.size()), geometry::kEpsilon)) {
    if (first < objects) {
      candidates.emplace_back(first, second);
    }
  }
  std::sort(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
    const auto rank = [&](const std::pair<std::size_t, std::size_t>& pair) {
      // An obstacle ranks before any object after the same object, in the obstacles' order.
      return std::make_tuple(pair.first, pair.second >= objects ? 0 : 1,
                             pair.second >= objects ? pair.second - objects : pair.second);
    };
    return rank(a) < rank(b);
  });
  for (const auto& [object, other] : candidates) {
    if (other >= objects) {
      const StaticObstacle& obstacle = world.obstacles[other - objects];
      if (interiorsOverlap(placed[object], obstacle.outline)) {
        problems.push_back({objectEntity(world.objects[object]), "overlaps " + obstacleEntity(obstacle)});
      }
    } else if (interiorsOverlap(placed[object], placed[other])) {
      problems.push_back(
          {objectEntity(world.objects[object]), "overlaps " + objectEntity(world.objects[other])});
    }
  }

  const auto start = world.start.position();
  if (const auto problem = poseProblem(world.start)) {
    problems.push_back({"start", *problem});
  }
  for (const auto& obstacle : world.obstacles) {
    if (geometry::containsPoint(obstacle.outline, start)) {
      problems.push_back({"start", "lies inside " + obstacleEntity(obstacle)});
    }
  }
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (geometry::containsPoint(placed[i], start)) {
      problems.push_back({"start", "lies inside " + objectEntity(world.objects[i])});
    }
  }
  for (const auto& goal : world.goals) {
    const std::string entity = "goal '" + goal.name + "'";
    if (!finite(goal.position)) {
      problems.push_back({entity, "position is not finite"});
      continue;
    }
    if (!withinExtent(goal.position)) {
      problems.push_back(
          {entity,
           "position lies beyond " + std::to_string(static_cast<int>(kMaxCoordinateM)) + " m of the origin"});
      continue;
    }
    for (const auto& obstacle : world.obstacles) {
      if (geometry::containsPoint(obstacle.outline, goal.position)) {
        problems.push_back({entity, "lies inside " + obstacleEntity(obstacle)});
      }
    }
  }
  return problems;
}

std::string describeProblems(const std::string& source, const std::vector<WorldProblem>& problems)
{
  if (problems.empty()) {
    return {};
  }
  std::string message = source + ": " + problems.front().entity + ": " + problems.front().problem;
  if (problems.size() > 1) {
    message += " (and " + std::to_string(problems.size() - 1) + " more problem" +
               (problems.size() > 2 ? "s" : "") + ")";
  }
  return message;
}

}  // namespace ifar::sim
