#include "executive/obstacles/local_obstacles.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"
#include "tests/unit/executive/vlp16_test_packet.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;
using geometry::Pose2;
using testing::TestPacket;

using ifar::geometry::kPi;
constexpr double kDegree = kPi / 180.0;
constexpr std::int64_t kStartUs = 1'700'000'000'000'000;

// Laser indices (firing order) and their elevations from the VLP-16 manual.
constexpr std::size_t kLaserMinus1 = 14;  // -1 degree
constexpr std::size_t kLaserMinus11 = 4;  // -11 degrees
constexpr std::size_t kLaserMinus15 = 0;  // -15 degrees
constexpr std::size_t kLaserPlus15 = 15;  // +15 degrees

common::ByteView view(const TestPacket& packet)
{
  return common::ByteView(packet.bytes().data(), packet.bytes().size());
}

class LocalObstaclesTest : public ::testing::Test {
 protected:
  LocalObstaclesTest() : obstacles_(settings_, vehicle_) {}

  ObstacleSettings settings_;
  common::VehicleSettings vehicle_;  // lidar 0.2 m ahead of the reference point, 0.8 m up
  LocalObstacles obstacles_;
};

TEST_F(LocalObstaclesTest, PlacesOneReturnExactlyInTheWorld)
{
  // Vehicle at (10, 5) facing +y. One return at azimuth 90 degrees (the sensor's right, -y), laser -1
  // degree, 5.000 m: 4.99924 m horizontally to the vehicle's right, 0.2 m ahead of the reference point;
  // facing +y, the vehicle's right is +x.
  obstacles_.addPose(kStartUs, Pose2{10.0, 5.0, kPi / 2.0});
  TestPacket packet(9000);
  packet.set(0, kLaserMinus1, 2500, 40);
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs + 1000));

  const std::vector<Point> points = obstacles_.points(kStartUs + 1000);
  ASSERT_EQ(points.size(), 1u);
  const double horizontal = 5.0 * std::cos(1.0 * kDegree);
  EXPECT_NEAR(points[0].x(), 10.0 + horizontal, 1e-5);
  EXPECT_NEAR(points[0].y(), 5.0 + vehicle_.lidar_x_m, 1e-5);
  EXPECT_EQ(obstacles_.newestPacketUtime(), kStartUs + 1000);
  EXPECT_EQ(obstacles_.malformedPackets(), 0);
  // Diffuse return: not movable.
  EXPECT_FALSE(obstacles_.movableCentroid(points[0], 0.5, kStartUs + 1000).has_value());
}

TEST_F(LocalObstaclesTest, PoseIsMovedOnToThePacketTime)
{
  // Poses 20 ms apart: 1 m/s along +x and 1 rad/s; the packet arrives 10 ms after the second pose.
  obstacles_.addPose(kStartUs, Pose2{0.0, 0.0, 0.0});
  obstacles_.addPose(kStartUs + 20'000, Pose2{0.02, 0.0, 0.02});
  TestPacket packet(0);
  packet.set(0, kLaserMinus1, 2500, 10);  // 5 m straight ahead of the lidar
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs + 30'000));
  const std::vector<Point> points = obstacles_.points(kStartUs + 30'000);
  ASSERT_EQ(points.size(), 1u);
  const double ahead = 5.0 * std::cos(1.0 * kDegree) + vehicle_.lidar_x_m;
  EXPECT_NEAR(points[0].x(), 0.03 + ahead * std::cos(0.03), 1e-5);
  EXPECT_NEAR(points[0].y(), ahead * std::sin(0.03), 1e-5);

  // A packet long after the last pose is placed at most 0.1 s on.
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs + 1'020'000));
  const std::vector<Point> late = obstacles_.points(kStartUs + 1'020'000);
  ASSERT_EQ(late.size(), 1u);
  EXPECT_NEAR(late[0].x(), 0.12 + ahead * std::cos(0.12), 1e-5);
}

TEST_F(LocalObstaclesTest, HeightAndRangeFilterInTheWorldFrame)
{
  obstacles_.addPose(kStartUs, Pose2{0.0, 0.0, 0.0});
  TestPacket packet(0);
  // World heights: 0.8 + r sin(elevation).
  packet.set(0, kLaserMinus11, 1500, 10);  // 3 m at -11 deg: 0.228 m, kept
  packet.set(1, kLaserMinus11, 2000, 10);  // 4 m at -11 deg: 0.037 m, ground
  packet.set(2, kLaserMinus15, 2500, 10);  // 5 m at -15 deg: below ground
  packet.set(3, kLaserPlus15, 2500, 10);   // 5 m at +15 deg: 2.09 m, overhead
  packet.set(4, kLaserMinus1, 150, 10);    // 0.3 m: the vehicle itself (min_range_m 0.4)
  packet.set(5, kLaserMinus1, 8000, 10);   // 16 m: beyond max_range_m 15
  packet.set(6, kLaserMinus1, 7000, 10);   // 14 m at 0.556 m height: kept
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs));
  const std::vector<Point> points = obstacles_.points(kStartUs);
  ASSERT_EQ(points.size(), 2u);
  // Block 0 at azimuth 0: straight ahead, 0.2 m lidar offset added.
  EXPECT_NEAR(points[0].x(), 3.0 * std::cos(11.0 * kDegree) + 0.2, 1e-5);
  EXPECT_NEAR(points[0].y(), 0.0, 1e-5);
  // Block 6 at azimuth 2.4 degrees (clockwise, so to the right).
  const double horizontal = 14.0 * std::cos(1.0 * kDegree);
  EXPECT_NEAR(points[1].x(), horizontal * std::cos(2.4 * kDegree) + 0.2, 1e-4);
  EXPECT_NEAR(points[1].y(), -horizontal * std::sin(2.4 * kDegree), 1e-4);
}

TEST_F(LocalObstaclesTest, PointsExpireAfterKeepTime)
{
  obstacles_.addPose(kStartUs, Pose2{0.0, 0.0, 0.0});
  TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 10);
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs));
  const auto keep_us = static_cast<std::int64_t>(settings_.keep_s * 1e6);
  EXPECT_EQ(obstacles_.points(kStartUs + keep_us).size(), 1u);
  EXPECT_TRUE(obstacles_.points(kStartUs + keep_us + 1).empty());

  // A newer packet keeps only its own point once the first has expired.
  TestPacket second(18000);
  second.set(0, kLaserMinus1, 1000, 10);
  ASSERT_TRUE(obstacles_.addPacket(view(second), kStartUs + 100'000));
  const std::vector<Point> later = obstacles_.points(kStartUs + 200'000);
  ASSERT_EQ(later.size(), 1u);
  EXPECT_LT(later[0].x(), 0.0);  // azimuth 180 degrees: behind the lidar
}

TEST_F(LocalObstaclesTest, MemoryIsBoundedUnderAPacketFlood)
{
  ObstacleSettings every_return = settings_;
  every_return.cell_m = 0.0;
  LocalObstacles obstacles(every_return, vehicle_);
  obstacles.addPose(kStartUs, Pose2{0.0, 0.0, 0.0});
  TestPacket packet(0);
  for (std::size_t block = 0; block < velodyne::kBlocksPerPacket; ++block) {
    packet.set(block, kLaserMinus1, 1000, 10);
  }
  // 5000 packets all "received" at once: far more than any lidar sends within keep_s.
  for (int index = 0; index < 5000; ++index) {
    ASSERT_TRUE(obstacles.addPacket(view(packet), kStartUs));
  }
  const std::size_t slots = static_cast<std::size_t>(std::ceil(settings_.keep_s * 1600.0)) + 8;
  EXPECT_EQ(obstacles.points(kStartUs).size(), slots * velodyne::kBlocksPerPacket);
}

TEST_F(LocalObstaclesTest, OnePointPerCellNewestFirst)
{
  obstacles_.addPose(kStartUs, Pose2{0.0, 0.025, 0.0});  // mid-cell in y (cells are 5 cm from 0)
  TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 10);  // 2 m ahead
  packet.set(1, kLaserMinus1, 1000, 10);  // 1.4 cm to its right: the same 5 cm cell
  packet.set(6, kLaserMinus1, 1000, 10);  // 8.4 cm to the right: another cell
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs));
  EXPECT_EQ(obstacles_.points(kStartUs).size(), 2u);
  // The same returns seen again from 1 cm further back: the newer ones stand for the cells.
  obstacles_.addPose(kStartUs + 1000, Pose2{-0.01, 0.025, 0.0});
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs + 1000));
  const std::vector<Point> points = obstacles_.points(kStartUs + 1000);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_NEAR(points[0].x(), 2.0 * std::cos(1.0 * kDegree) + 0.2 - 0.01, 1e-5);
}

TEST_F(LocalObstaclesTest, MovableCentroidOfRetroReflectiveReturns)
{
  obstacles_.addPose(kStartUs, Pose2{0.0, 0.0, 0.0});
  TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 200);  // 2 m ahead, retro-reflective
  packet.set(6, kLaserMinus1, 1000, 255);  // 2 m at azimuth 2.4 degrees, retro-reflective
  packet.set(11, kLaserMinus1, 1000, 30);  // 2 m at azimuth 4.4 degrees, diffuse: background
  ASSERT_TRUE(obstacles_.addPacket(view(packet), kStartUs));
  EXPECT_EQ(obstacles_.points(kStartUs).size(), 3u);
  const std::optional<Point> centroid = obstacles_.movableCentroid(Point(2.2, 0.0), 0.5, kStartUs);
  ASSERT_TRUE(centroid.has_value());
  const double horizontal = 2.0 * std::cos(1.0 * kDegree);
  EXPECT_NEAR(centroid->x(), 0.2 + horizontal * (1.0 + std::cos(2.4 * kDegree)) / 2.0, 1e-5);
  EXPECT_NEAR(centroid->y(), -horizontal * std::sin(2.4 * kDegree) / 2.0, 1e-5);
  EXPECT_FALSE(obstacles_.movableCentroid(Point(-2.0, 0.0), 0.5, kStartUs).has_value());
  EXPECT_FALSE(obstacles_.movableCentroid(Point(2.2, 0.0), 0.5, kStartUs + 1'000'000).has_value());
}

TEST_F(LocalObstaclesTest, MalformedPacketsAreCountedAndSkipped)
{
  obstacles_.addPose(kStartUs, Pose2{0.0, 0.0, 0.0});
  TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 10);

  std::vector<std::uint8_t> truncated = packet.bytes();
  truncated.pop_back();
  EXPECT_FALSE(obstacles_.addPacket(common::ByteView(truncated.data(), truncated.size()), kStartUs));

  TestPacket bad_marker = packet;
  bad_marker.bytes()[5 * velodyne::kBlockSize + 1] = 0x00;
  EXPECT_FALSE(obstacles_.addPacket(view(bad_marker), kStartUs));

  TestPacket bad_product = packet;
  bad_product.bytes()[velodyne::kProductIdOffset] = 0x21;
  EXPECT_FALSE(obstacles_.addPacket(view(bad_product), kStartUs));

  EXPECT_FALSE(obstacles_.addPacket(common::ByteView(), kStartUs));
  EXPECT_EQ(obstacles_.malformedPackets(), 4);
  EXPECT_TRUE(obstacles_.points(kStartUs).empty());
  EXPECT_EQ(obstacles_.newestPacketUtime(), 0);

  EXPECT_TRUE(obstacles_.addPacket(view(packet), kStartUs));
  EXPECT_EQ(obstacles_.points(kStartUs).size(), 1u);
  EXPECT_EQ(obstacles_.malformedPackets(), 4);
}

TEST_F(LocalObstaclesTest, PacketsBeforeAnyPoseAreDroppedNotMalformed)
{
  TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 10);
  EXPECT_FALSE(obstacles_.addPacket(view(packet), kStartUs));
  EXPECT_EQ(obstacles_.packetsWithoutPose(), 1);
  EXPECT_EQ(obstacles_.malformedPackets(), 0);
  // A non-finite pose is no pose either.
  obstacles_.addPose(kStartUs, Pose2{std::nan(""), 0.0, 0.0});
  EXPECT_FALSE(obstacles_.addPacket(view(packet), kStartUs));
  EXPECT_EQ(obstacles_.packetsWithoutPose(), 2);
}

TEST(ObstacleSettings, LoadsShippedConfig)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/executive.yaml");
  const ObstacleSettings settings = loadObstacleSettings(root.child("obstacles"));
  EXPECT_EQ(settings.packet_channel, "VELODYNE_PACKET");
  EXPECT_DOUBLE_EQ(settings.max_range_m, 15.0);
  EXPECT_DOUBLE_EQ(settings.keep_s, 0.15);
  EXPECT_DOUBLE_EQ(settings.cell_m, 0.05);
}

std::string loadError(const std::string& text)
{
  try {
    loadObstacleSettings(common::ConfigNode::loadString(text, "obstacles.yaml"));
  } catch (const common::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(ObstacleSettings, BadValuesNameTheKey)
{
  const std::string valid = "packet_channel: VELODYNE_PACKET\nmax_range_m: 15\ncell_m: 0.05\n";
  EXPECT_EQ(loadError(valid + "keep_s: 0.15\n"), "");
  EXPECT_NE(loadError(valid + "keep_s: 0.15\nsurprise: 1\n").find("surprise"), std::string::npos);
  // The lidar filter is the vehicle's (vehicle.yaml lidar:), no longer a key of this section.
  EXPECT_NE(loadError(valid + "keep_s: 0.15\nmin_range_m: 0.4\n").find("'min_range_m': unknown key"),
            std::string::npos);
  EXPECT_NE(loadError(valid).find("keep_s"), std::string::npos);
  EXPECT_EQ(loadError(valid + "keep_s: -1\n"), "obstacles.yaml: key 'keep_s': must be in (0, 2] s, got -1");
  EXPECT_EQ(loadError(valid + "keep_s: 3\n"), "obstacles.yaml: key 'keep_s': must be in (0, 2] s, got 3");
}

}  // namespace
}  // namespace ifar::executive
