#include "sim/lidar/lidar_scene.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "sim/simulator/builtin_worlds.hpp"

namespace ifar::sim::lidar {
namespace {

using geometry::Point;

constexpr double kDegree = M_PI / 180.0;

geometry::Polygon box(double low_x, double low_y, double high_x, double high_y)
{
  return {Point(low_x, low_y), Point(high_x, low_y), Point(high_x, high_y), Point(low_x, high_y)};
}

Ray rayAlongX(double elevation_deg, double max_horizontal = 100.0)
{
  Ray ray;
  ray.height = 0.8;
  ray.slope = std::tan(elevation_deg * kDegree);
  ray.max_horizontal = max_horizontal;
  return ray;
}

TEST(LidarScene, HorizontalRayHitsTheWallFace)
{
  const LidarScene scene({{box(10.0, -1.0, 11.0, 1.0), 2.0, 0.3}}, LidarSceneSettings{});
  const RayHit hit = scene.cast(rayAlongX(1.0));
  EXPECT_EQ(hit.surface, RayHit::Surface::Wall);
  EXPECT_NEAR(hit.horizontal_distance, 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(hit.reflectivity, 0.3);
}

TEST(LidarScene, LowObjectIsSeenOnlyByDownwardLasers)
{
  // A 0.5 m high block from x = 2 to 4; the sensor is 0.8 m up.
  const LidarScene scene({{box(2.0, -1.0, 4.0, 1.0), 0.5, 0.9}}, LidarSceneSettings{});
  const RayHit upward = scene.cast(rayAlongX(1.0, 20.0));
  EXPECT_EQ(upward.surface, RayHit::Surface::None);
  // -15 degrees reaches 0.264 m height at the face: hits the face.
  const RayHit steep = scene.cast(rayAlongX(-15.0));
  EXPECT_EQ(steep.surface, RayHit::Surface::Wall);
  EXPECT_NEAR(steep.horizontal_distance, 2.0, 1e-12);
  // -7 degrees passes over the face (0.554 m) and lands on the top at 0.3 / tan(7 deg).
  const RayHit shallow = scene.cast(rayAlongX(-7.0));
  EXPECT_EQ(shallow.surface, RayHit::Surface::Top);
  EXPECT_NEAR(shallow.horizontal_distance, 0.3 / std::tan(7.0 * kDegree), 1e-12);
  EXPECT_DOUBLE_EQ(shallow.reflectivity, 0.9);
  // -3 degrees passes over the whole block (top reached only at 5.7 m) and hits the ground at 15.3 m.
  const RayHit grazing = scene.cast(rayAlongX(-3.0));
  EXPECT_EQ(grazing.surface, RayHit::Surface::Ground);
  EXPECT_NEAR(grazing.horizontal_distance, 0.8 / std::tan(3.0 * kDegree), 1e-9);
}

TEST(LidarScene, GroundBeyondRangeIsNoReturn)
{
  const LidarScene scene(std::vector<Prism>{}, LidarSceneSettings{});
  EXPECT_EQ(scene.cast(rayAlongX(-1.0, 40.0)).surface, RayHit::Surface::None);  // ground at 45.8 m
  EXPECT_EQ(scene.cast(rayAlongX(-1.0, 50.0)).surface, RayHit::Surface::Ground);
}

TEST(LidarScene, MovablesAreHitAndOccludeWalls)
{
  LidarScene scene({{box(10.0, -1.0, 11.0, 1.0), 2.0, 0.2}}, LidarSceneSettings{});
  scene.setMovables({{box(5.0, -0.3, 5.6, 0.3), 1.0, 0.9}});
  const RayHit hit = scene.cast(rayAlongX(1.0));
  EXPECT_EQ(hit.surface, RayHit::Surface::Wall);
  EXPECT_NEAR(hit.horizontal_distance, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(hit.reflectivity, 0.9);
  // The same movable seen from behind the wall does not hide it.
  scene.setMovables({{box(12.0, -0.3, 12.6, 0.3), 1.0, 0.9}});
  EXPECT_NEAR(scene.cast(rayAlongX(1.0)).horizontal_distance, 10.0, 1e-12);
}

/// Reference: every segment of every wall, no grid (walls are taller than the sensor, so no tops).
double bruteForceDistance(const World& world, const Ray& ray, double limit)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& obstacle : world.obstacles) {
    for (std::size_t index = 0; index < obstacle.outline.size(); ++index) {
      const Point start = obstacle.outline[index];
      const Point end = obstacle.outline[(index + 1) % obstacle.outline.size()];
      const Point delta = end - start;
      const double denominator = ray.direction_x * delta.y() - ray.direction_y * delta.x();
      if (std::abs(denominator) < 1e-12) {
        continue;
      }
      const Point offset = start - Point(ray.origin_x, ray.origin_y);
      const double along_ray = (offset.x() * delta.y() - offset.y() * delta.x()) / denominator;
      const double along_segment =
          (offset.x() * ray.direction_y - offset.y() * ray.direction_x) / denominator;
      const double height = ray.height + ray.slope * along_ray;
      if (along_ray > 0.0 && along_segment >= 0.0 && along_segment <= 1.0 && along_ray <= limit &&
          height >= 0.0 && height <= obstacle.height_m) {
        best = std::min(best, along_ray);
      }
    }
  }
  return best;
}

TEST(LidarScene, GridWalkAgreesWithBruteForceOnTheTunnelNetwork)
{
  const World world = builtinTunnelNetwork();
  ASSERT_GT(world.obstacles.size(), 300u);
  const LidarScene scene = LidarScene::fromWorld(world, LidarSceneSettings{});
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> x_position(1.0, 329.0);
  std::uniform_real_distribution<double> y_position(1.0, 269.0);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_int_distribution<int> laser(-15, 15);
  int walls = 0;
  for (int index = 0; index < 3000; ++index) {
    Ray ray;
    ray.origin_x = x_position(random);
    ray.origin_y = y_position(random);
    ray.height = 0.8;
    const double direction = angle(random);
    ray.direction_x = std::cos(direction);
    ray.direction_y = std::sin(direction);
    const double elevation = laser(random) * kDegree;
    ray.slope = std::tan(elevation);
    ray.max_horizontal = 100.0 * std::cos(elevation);
    double limit = ray.max_horizontal;
    if (ray.slope < 0.0) {
      limit = std::min(limit, ray.height / -ray.slope);
    }
    const double expected = bruteForceDistance(world, ray, limit);
    const RayHit hit = scene.cast(ray);
    if (std::isfinite(expected)) {
      ++walls;
      ASSERT_EQ(hit.surface, RayHit::Surface::Wall) << "ray " << index;
      ASSERT_NEAR(hit.horizontal_distance, expected, 1e-9) << "ray " << index;
    } else {
      ASSERT_NE(hit.surface, RayHit::Surface::Wall) << "ray " << index;
    }
  }
  EXPECT_GT(walls, 1000);
}

}  // namespace
}  // namespace ifar::sim::lidar
