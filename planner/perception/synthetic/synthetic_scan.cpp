#include "planner/perception/synthetic/synthetic_scan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/geometry/angle.hpp"

namespace ifar::perception::synthetic {
namespace {

SensorPoint toSensor(const Eigen::Vector3d& world, const Eigen::Isometry3d& world_to_sensor,
                     float reflectivity, double time_offset_s)
{
  SensorPoint point;
  point.position_sensor = (world_to_sensor * world).cast<float>();
  point.reflectivity = reflectivity;
  point.time_offset_s = time_offset_s;
  return point;
}

/// Distance along the unit 2-D ray from `origin` to the segment, when the ray meets it.
std::optional<double> rayHit(const geometry::Point& origin, const geometry::Vector& direction,
                             const geometry::Segment& segment)
{
  const geometry::Vector edge = segment.end - segment.start;
  const double denominator = geometry::cross(direction, edge);
  if (std::abs(denominator) < 1e-12) {
    return std::nullopt;
  }
  const geometry::Vector offset = segment.start - origin;
  const double along_ray = geometry::cross(offset, edge) / denominator;
  const double along_edge = geometry::cross(offset, direction) / denominator;
  if (along_ray <= 0.0 || along_edge < 0.0 || along_edge > 1.0) {
    return std::nullopt;
  }
  return along_ray;
}

}  // namespace

geometry::Polygon boxFootprint(double centre_x, double centre_y, double size_x, double size_y)
{
  const double half_x = 0.5 * size_x;
  const double half_y = 0.5 * size_y;
  return {geometry::Point(centre_x - half_x, centre_y - half_y),
          geometry::Point(centre_x + half_x, centre_y - half_y),
          geometry::Point(centre_x + half_x, centre_y + half_y),
          geometry::Point(centre_x - half_x, centre_y + half_y)};
}

std::vector<SensorPoint> sampleObstacleFaces(const std::vector<PrismObstacle>& obstacles,
                                             const std::vector<double>& heights_m, double spacing_m,
                                             const Eigen::Isometry3d& sensor_to_world)
{
  const Eigen::Isometry3d world_to_sensor = sensor_to_world.inverse();
  std::vector<SensorPoint> points;
  for (const PrismObstacle& obstacle : obstacles) {
    for (std::size_t index = 0; index < obstacle.footprint.size(); ++index) {
      const geometry::Segment face = geometry::polygonEdge(obstacle.footprint, index);
      const int steps = std::max(1, static_cast<int>(std::ceil(face.length() / spacing_m - 1e-9)));
      for (int step = 0; step <= steps; ++step) {
        const geometry::Point ground =
            face.start + (face.end - face.start) * (static_cast<double>(step) / steps);
        for (const double height : heights_m) {
          points.push_back(toSensor(Eigen::Vector3d(ground.x(), ground.y(), height), world_to_sensor,
                                    obstacle.reflectivity, 0.0));
        }
      }
    }
  }
  return points;
}

std::vector<SensorPoint> simulateRevolution(const std::vector<PrismObstacle>& obstacles,
                                            const Eigen::Isometry3d& sensor_to_world,
                                            const RevolutionSettings& settings)
{
  const Eigen::Vector3d sensor = sensor_to_world.translation();
  const geometry::Point origin(sensor.x(), sensor.y());
  const Eigen::Vector3d forward = sensor_to_world.linear() * Eigen::Vector3d::UnitX();
  const double yaw = std::atan2(forward.y(), forward.x());
  const Eigen::Isometry3d world_to_sensor = sensor_to_world.inverse();
  const int azimuth_steps = static_cast<int>(std::lround(360.0 / settings.azimuth_step_deg));
  std::vector<SensorPoint> points;
  points.reserve(static_cast<std::size_t>(azimuth_steps) * 16);
  for (int azimuth_index = 0; azimuth_index < azimuth_steps; ++azimuth_index) {
    const double azimuth = yaw + geometry::radiansFromDegrees(azimuth_index * settings.azimuth_step_deg);
    const geometry::Vector direction(std::cos(azimuth), std::sin(azimuth));
    const double time_offset = settings.duration_s * azimuth_index / azimuth_steps;
    // Horizontal distances to every face the ray crosses, with the face's obstacle.
    std::vector<std::pair<double, const PrismObstacle*>> crossings;
    for (const PrismObstacle& obstacle : obstacles) {
      for (std::size_t index = 0; index < obstacle.footprint.size(); ++index) {
        if (const auto hit = rayHit(origin, direction, geometry::polygonEdge(obstacle.footprint, index))) {
          crossings.emplace_back(*hit, &obstacle);
        }
      }
    }
    std::sort(crossings.begin(), crossings.end(),
              [](const auto& first, const auto& second) { return first.first < second.first; });
    for (int laser = 0; laser < 16; ++laser) {
      const double elevation = geometry::radiansFromDegrees(-15.0 + 2.0 * laser);
      const double slope = std::tan(elevation);
      double best = settings.max_range_m;
      float reflectivity = 0.0F;
      bool found = false;
      for (const auto& [distance, obstacle] : crossings) {
        const double height = sensor.z() + distance * slope;
        if (height >= 0.0 && height <= obstacle->height_m) {
          best = distance;
          reflectivity = obstacle->reflectivity;
          found = true;
          break;
        }
      }
      const auto consider_plane = [&](double plane_height, float plane_reflectivity) {
        const double distance = (plane_height - sensor.z()) / slope;
        if (distance > 0.0 && distance < best) {
          best = distance;
          reflectivity = plane_reflectivity;
          found = true;
        }
      };
      if (slope < 0.0) {
        consider_plane(0.0, 10.0F);
      } else if (slope > 0.0 && settings.ceiling_height_m) {
        consider_plane(*settings.ceiling_height_m, 10.0F);
      }
      if (!found || best / std::cos(elevation) > settings.max_range_m) {
        continue;
      }
      const Eigen::Vector3d hit(origin.x() + best * direction.x(), origin.y() + best * direction.y(),
                                sensor.z() + best * slope);
      points.push_back(toSensor(hit, world_to_sensor, reflectivity, time_offset));
    }
  }
  return points;
}

std::vector<PrismObstacle> roomWithBoxes()
{
  constexpr float kWall = 30.0F;
  constexpr float kTagged = 200.0F;
  std::vector<PrismObstacle> world = {
      {boxFootprint(0.0, 16.1, 32.4, 0.2), 2.5, kWall},  {boxFootprint(0.0, -16.1, 32.4, 0.2), 2.5, kWall},
      {boxFootprint(16.1, 0.0, 0.2, 32.0), 2.5, kWall},  {boxFootprint(-16.1, 0.0, 0.2, 32.0), 2.5, kWall},
      {boxFootprint(5.0, 3.0, 2.0, 1.0), 1.0, kWall},    {boxFootprint(-6.0, 4.0, 1.5, 1.5), 0.8, kWall},
      {boxFootprint(-4.0, -7.0, 3.0, 0.6), 1.5, kWall},  {boxFootprint(9.0, -9.0, 1.0, 4.0), 2.0, kWall},
      {boxFootprint(10.0, 10.0, 2.0, 2.0), 1.2, kWall},  {boxFootprint(3.0, -3.0, 0.8, 0.8), 0.6, kTagged},
      {boxFootprint(-2.5, 2.5, 1.0, 0.6), 0.7, kTagged}, {boxFootprint(0.0, 8.0, 1.2, 1.2), 0.9, kTagged},
  };
  return world;
}

}  // namespace ifar::perception::synthetic
