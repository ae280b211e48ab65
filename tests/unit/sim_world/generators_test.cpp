#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <queue>
#include <string>

#include "common/vehicle.hpp"
#include "sim/generators/generators.hpp"
#include "sim/world/world_file.hpp"
#include "sim/world/world_geometry.hpp"

namespace ifar::sim {
namespace {

const WorldKind kSeededKinds[] = {WorldKind::Room,   WorldKind::RoomObjects,   WorldKind::Office,
                                  WorldKind::Tunnel, WorldKind::BlockedOffice, WorldKind::BlockedTunnel};

/// Length of the shortest 8-connected path between start and first goal over grid cells whose centres lie
/// outside every static obstacle (movable objects ignored): the "short cut" length.
double staticPathLength(const World& world, double cell)
{
  const int width = static_cast<int>(std::ceil((world.bounds_max.x() - world.bounds_min.x()) / cell));
  const int height = static_cast<int>(std::ceil((world.bounds_max.y() - world.bounds_min.y()) / cell));
  auto centre = [&](int x, int y) -> geometry::Point {
    return world.bounds_min + geometry::Point((x + 0.5) * cell, (y + 0.5) * cell);
  };
  std::vector<char> free(static_cast<std::size_t>(width * height), 1);
  for (const auto& obstacle : world.obstacles) {
    geometry::Point low = obstacle.outline.front();
    geometry::Point high = low;
    for (const auto& vertex : obstacle.outline) {
      low = low.cwiseMin(vertex);
      high = high.cwiseMax(vertex);
    }
    const int x0 = std::max(0, static_cast<int>((low.x() - world.bounds_min.x()) / cell) - 1);
    const int x1 = std::min(width - 1, static_cast<int>((high.x() - world.bounds_min.x()) / cell) + 1);
    const int y0 = std::max(0, static_cast<int>((low.y() - world.bounds_min.y()) / cell) - 1);
    const int y1 = std::min(height - 1, static_cast<int>((high.y() - world.bounds_min.y()) / cell) + 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (geometry::containsPoint(obstacle.outline, centre(x, y))) {
          free[static_cast<std::size_t>(y * width + x)] = 0;
        }
      }
    }
  }
  auto cellOf = [&](const geometry::Point& point) {
    const int x = static_cast<int>((point.x() - world.bounds_min.x()) / cell);
    const int y = static_cast<int>((point.y() - world.bounds_min.y()) / cell);
    return y * width + x;
  };
  std::vector<double> distance(free.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  const int source = cellOf(world.start.position());
  const int target = cellOf(world.goals.at(0).position);
  distance[static_cast<std::size_t>(source)] = 0.0;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [cost, node] = queue.top();
    queue.pop();
    if (node == target) {
      return cost * cell;
    }
    if (cost > distance[static_cast<std::size_t>(node)]) {
      continue;
    }
    const int x = node % width;
    const int y = node / width;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx;
        const int ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) {
          continue;
        }
        const int next = ny * width + nx;
        // Diagonal steps need both side cells free (no corner cutting).
        if (!free[static_cast<std::size_t>(next)] || !free[static_cast<std::size_t>(y * width + nx)] ||
            !free[static_cast<std::size_t>(ny * width + x)]) {
          continue;
        }
        const double step = (dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0;
        if (cost + step < distance[static_cast<std::size_t>(next)]) {
          distance[static_cast<std::size_t>(next)] = cost + step;
          queue.push({cost + step, next});
        }
      }
    }
  }
  return std::numeric_limits<double>::infinity();
}

TEST(SimWorldGenerators, SameSeedGivesSameWorld)
{
  for (const auto kind : kSeededKinds) {
    const auto first = generateWorld(kind, 42);
    const auto second = generateWorld(kind, 42);
    ASSERT_TRUE(first.ok()) << first.error();
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_EQ(formatWorld(first.world()), formatWorld(second.world())) << worldKindName(kind);
  }
}

TEST(SimWorldGenerators, DifferentSeedsGiveDifferentWorlds)
{
  for (const auto kind : kSeededKinds) {
    EXPECT_NE(formatWorld(generateWorld(kind, 1).world()), formatWorld(generateWorld(kind, 2).world()))
        << worldKindName(kind);
  }
}

TEST(SimWorldGenerators, GeneratedWorldsPassValidationForManySeeds)
{
  for (const auto kind : kSeededKinds) {
    for (std::uint64_t seed = 0; seed < 15; ++seed) {
      const auto result = generateWorld(kind, seed);
      EXPECT_TRUE(result.ok()) << worldKindName(kind) << " seed " << seed << ": " << result.error();
    }
  }
}

TEST(SimWorldGenerators, RoomWithObjectsSharesTheStaticLayout)
{
  const World plain = generateRoom(5, false);
  const World with_objects = generateRoom(5, true);
  EXPECT_TRUE(plain.objects.empty());
  EXPECT_FALSE(with_objects.objects.empty());
  ASSERT_EQ(plain.obstacles.size(), with_objects.obstacles.size());
  for (std::size_t index = 0; index < plain.obstacles.size(); ++index) {
    EXPECT_EQ(plain.obstacles[index].outline, with_objects.obstacles[index].outline);
  }
  EXPECT_DOUBLE_EQ(plain.bounds_max.x() - plain.bounds_min.x(), 32.0);
  EXPECT_DOUBLE_EQ(plain.bounds_max.y() - plain.bounds_min.y(), 32.0);
}

TEST(SimWorldGenerators, LightAndHeavyObjectsStraddleThePushLimit)
{
  const common::VehicleSettings vehicle;
  ASSERT_NEAR(vehicle.maxPushForce(), 549.36, 1e-9);
  for (const auto kind :
       {WorldKind::RoomObjects, WorldKind::Office, WorldKind::Tunnel, WorldKind::DemoRoom}) {
    const auto result = generateWorld(kind, 3);
    ASSERT_TRUE(result.ok()) << result.error();
    int light = 0;
    int heavy = 0;
    for (const auto& object : result.world().objects) {
      const double force = slidingForce(object);
      if (force < 0.5 * vehicle.maxPushForce()) {
        ++light;
      } else if (force > 2.0 * vehicle.maxPushForce()) {
        ++heavy;
      } else {
        ADD_FAILURE() << worldKindName(kind) << " object '" << object.name << "' needs " << force
                      << " N: neither clearly light nor clearly heavy";
      }
    }
    EXPECT_GT(light, 0) << worldKindName(kind);
    EXPECT_GT(heavy, 0) << worldKindName(kind);
  }
}

TEST(SimWorldGenerators, OfficeFireDoorBoxIsHeavyForOddSeedsAndLightForEvenOnes)
{
  const common::VehicleSettings vehicle;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const World office = generateOffice(seed);
    // The fire door's box stands in the corridor's middle (y 12), the only object there.
    int found = 0;
    for (const auto& object : office.objects) {
      if (std::abs(object.pose.y - 12.0) < 1e-9) {
        ++found;
        EXPECT_EQ(slidingForce(object) > vehicle.maxPushForce(), seed % 2 == 1)
            << "seed " << seed << " '" << object.name << "' needs " << slidingForce(object) << " N";
      }
    }
    EXPECT_EQ(found, 1) << "seed " << seed;
  }
}

TEST(SimWorldGenerators, PathLengthsMatchThePapersPlaces)
{
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const double room = staticPathLength(generateRoom(seed, false), 0.25);
    EXPECT_GT(room, 15.0) << "room seed " << seed;  // the paper's threshold for the 32 m room
    EXPECT_LT(room, 45.0) << "room seed " << seed;
    const double office = staticPathLength(generateOffice(seed), 0.25);
    EXPECT_GT(office, 40.0) << "office seed " << seed;
    EXPECT_LT(office, 65.0) << "office seed " << seed;
    const World tunnel = generateTunnel(seed);
    EXPECT_NEAR(tunnel.bounds_max.x() - tunnel.bounds_min.x(), 330.0, 1e-9);
    EXPECT_NEAR(tunnel.bounds_max.y() - tunnel.bounds_min.y(), 270.0, 1e-9);
    const double tunnel_path = staticPathLength(tunnel, 1.0);
    EXPECT_GT(tunnel_path, 380.0) << "tunnel seed " << seed;
    EXPECT_LT(tunnel_path, 520.0) << "tunnel seed " << seed;
  }
}

/// The world with `outline` as one more static obstacle.
World withPlug(const World& world, const geometry::Polygon& outline)
{
  World plugged = world;
  StaticObstacle plug;
  plug.name = "plug";
  plug.outline = outline;
  plugged.obstacles.push_back(plug);
  return plugged;
}

/// Shortest static path length between two points of `world` (0.5 m cells).
double pathBetween(World world, const geometry::Point& from, const geometry::Point& to)
{
  world.start = geometry::Pose2{from.x(), from.y(), 0.0};
  world.goals.at(0).position = to;
  return staticPathLength(world, 0.5);
}

bool insideStatic(const World& world, const geometry::Point& point)
{
  for (const StaticObstacle& obstacle : world.obstacles) {
    if (geometry::containsPoint(obstacle.outline, point)) {
      return true;
    }
  }
  return false;
}

TEST(SimWorldGenerators, TunnelCratesArePushedIntoTheNextJunctionAndClearItsTurn)
{
  // A crate fills its tunnel's width, so the vehicle can only push it ahead along the tunnel. Each one
  // stands just short of a junction whose side tunnel is open: from behind the crate, the turn into that
  // side tunnel is closed with the crate in place, and open once the crate is pushed 4 m ahead (the
  // interaction planner's search_radius_m). A crate mid-tunnel or in a dead end (seed 1 before) fails.
  constexpr double kPushM = 4.0;
  int crates = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const World tunnel = generateTunnel(seed);
    for (const MovableObject& object : tunnel.objects) {
      const geometry::Polygon outline = placedOutline(object);
      geometry::Point low = outline.front();
      geometry::Point high = low;
      for (const geometry::Point& vertex : outline) {
        low = low.cwiseMin(vertex);
        high = high.cwiseMax(vertex);
      }
      const geometry::Point extent = high - low;
      if (extent.maxCoeff() < 3.0) {
        continue;  // a loose box against a tunnel side
      }
      ++crates;
      const std::string name = "seed " + std::to_string(seed) + " " + object.name;
      const geometry::Point centre = 0.5 * (low + high);
      const geometry::Point axis =
          extent.x() < extent.y() ? geometry::Point(1.0, 0.0) : geometry::Point(0.0, 1.0);
      const geometry::Point across(-axis.y(), axis.x());
      // Ahead: toward the nearer junction with an open side tunnel (3 m off the tunnel's centre line).
      double mouth = -1.0;
      geometry::Point ahead = axis;
      double side = 1.0;
      for (double along = 0.0; along < 60.0 && mouth < 0.0; along += 0.1) {
        for (const double direction : {1.0, -1.0}) {
          for (const double lateral : {1.0, -1.0}) {
            const geometry::Point probe = centre + direction * along * axis + lateral * 3.0 * across;
            if (mouth < 0.0 && !insideStatic(tunnel, probe)) {
              mouth = along;
              ahead = direction * axis;
              side = lateral;
            }
          }
        }
      }
      ASSERT_GE(mouth, 0.0) << name;
      const geometry::Point behind = centre - 2.5 * ahead;
      const geometry::Point turned = centre + (mouth + 2.0) * ahead + side * 6.0 * across;
      const double turn_length = (mouth + 4.5) + 6.0 + 1.0;  // round the corner, with slack for the cells
      // The crate as the vehicle sees it: no way past its ends (0.2 m from the rock, the vehicle is 0.7 m).
      const auto plug = [&](double pushed_m) {
        const geometry::Point grow = 0.5 * across.cwiseAbs();
        const geometry::Point from = low - grow + pushed_m * ahead;
        const geometry::Point to = high + grow + pushed_m * ahead;
        return geometry::Polygon{
            {from.x(), from.y()}, {to.x(), from.y()}, {to.x(), to.y()}, {from.x(), to.y()}};
      };
      EXPECT_LE(pathBetween(withPlug(tunnel, plug(kPushM)), behind, turned), turn_length)
          << name << ": the junction " << mouth << " m ahead";
      EXPECT_GT(pathBetween(withPlug(tunnel, plug(0.0)), behind, turned), turn_length) << name;
    }
  }
  EXPECT_GT(crates, 3);
}

TEST(SimWorldGenerators, DemoRoomHidesTheGoalBehindALightDoorwayBox)
{
  const World demo = generateDemoRoom();
  const common::VehicleSettings vehicle;
  // The doorway box is the first object; the straight line from start to goal passes through it.
  const auto& doorway = demo.objects.at(0);
  EXPECT_TRUE(isPushable(doorway, vehicle));
  const auto outline = placedOutline(doorway);
  const geometry::Point start = demo.start.position();
  const geometry::Point goal = demo.goals.at(0).position;
  const geometry::Segment sight{start, goal};
  bool crosses = false;
  for (std::size_t index = 0; index < outline.size(); ++index) {
    crosses = crosses || geometry::segmentsIntersect(sight, geometry::polygonEdge(outline, index));
  }
  EXPECT_TRUE(crosses);
  // Without pushing, the way round through the opening is much longer than the straight line.
  const double straight = (goal - start).norm();
  EXPECT_GT(staticPathLength(withPlug(demo, outline), 0.25), 1.6 * straight);  // about 40 m against 22 m
}

TEST(SimWorldGenerators, KindNamesRoundTrip)
{
  for (const auto kind :
       {WorldKind::Room, WorldKind::RoomObjects, WorldKind::Office, WorldKind::Tunnel, WorldKind::DemoRoom}) {
    EXPECT_EQ(parseWorldKind(worldKindName(kind)), kind);
  }
  EXPECT_FALSE(parseWorldKind("castle").has_value());
}

}  // namespace
}  // namespace ifar::sim

namespace ifar::sim {
namespace {

TEST(SimWorldCheckedIn, LoadAndMatchTheirGenerator)
{
  const std::pair<const char*, WorldKind> files[] = {{"room.yaml", WorldKind::Room},
                                                     {"room_objects.yaml", WorldKind::RoomObjects},
                                                     {"office.yaml", WorldKind::Office},
                                                     {"tunnel.yaml", WorldKind::Tunnel},
                                                     {"demo_room.yaml", WorldKind::DemoRoom},
                                                     {"blocked_office.yaml", WorldKind::BlockedOffice},
                                                     {"blocked_tunnel.yaml", WorldKind::BlockedTunnel}};
  for (const auto& [file, kind] : files) {
    const std::string path = std::string(IFAR_SOURCE_DIR) + "/config/worlds/" + file;
    const auto loaded = loadWorldFile(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(formatWorld(loaded.world()), formatWorld(generateWorld(kind, 1).world()))
        << path << " differs from its generator: regenerate with "
        << "ifar-worldgen --kind " << worldKindName(kind) << " --seed 1 --out config/worlds/" << file;
  }
}

}  // namespace
}  // namespace ifar::sim
