#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/velodyne/packet_decoder.hpp"
#include "sim/lidar/vlp16_packet_encoder.hpp"
#include "sim/lidar/vlp16_scanner.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::sim::lidar {
namespace {

constexpr double kDegree = M_PI / 180.0;

TEST(Vlp16PacketEncoder, WritesTheBytesOfTheSensorFormat)
{
  std::array<Vlp16Block, kVlp16BlocksPerPacket> blocks{};
  blocks[0].azimuth_centidegrees = 12345;    // 0x3039
  blocks[0].first.distance_units[0] = 5000;  // 0x1388 = 10 m
  blocks[0].first.reflectivity[0] = 230;
  blocks[0].second.distance_units[15] = 0xABCD;
  blocks[0].second.reflectivity[15] = 7;
  blocks[11].azimuth_centidegrees = 35999;
  const Vlp16Packet packet = encodeVlp16Packet(blocks, 0x01020304u);
  ASSERT_EQ(packet.size(), 1206u);
  EXPECT_EQ(packet[0], 0xFF);
  EXPECT_EQ(packet[1], 0xEE);
  EXPECT_EQ(packet[2], 0x39);
  EXPECT_EQ(packet[3], 0x30);
  EXPECT_EQ(packet[4], 0x88);
  EXPECT_EQ(packet[5], 0x13);
  EXPECT_EQ(packet[6], 230);
  // Second firing, laser 15: block offset 4 + 31 x 3.
  EXPECT_EQ(packet[4 + 93], 0xCD);
  EXPECT_EQ(packet[4 + 94], 0xAB);
  EXPECT_EQ(packet[4 + 95], 7);
  EXPECT_EQ(packet[1100], 0xFF);
  EXPECT_EQ(packet[1101], 0xEE);
  EXPECT_EQ(packet[1102], 0x9F);  // 35999 = 0x8C9F
  EXPECT_EQ(packet[1103], 0x8C);
  EXPECT_EQ(packet[1200], 0x04);
  EXPECT_EQ(packet[1201], 0x03);
  EXPECT_EQ(packet[1202], 0x02);
  EXPECT_EQ(packet[1203], 0x01);
  EXPECT_EQ(packet[1204], 0x37);
  EXPECT_EQ(packet[1205], 0x22);
}

/// Expected slant range in the empty builtin room (inner faces at 0.2 and size - 0.2, walls 2 m high)
/// from the sensor at (x, y, 0.8), computed without the simulator's ray caster. 0 = no return.
double roomRange(double size, double sensor_x, double sensor_y, double direction, double elevation)
{
  const double low = 0.2;
  const double high = size - 0.2;
  const double cosine = std::cos(direction);
  const double sine = std::sin(direction);
  double wall = std::numeric_limits<double>::infinity();
  if (cosine > 1e-12)
    wall = std::min(wall, (high - sensor_x) / cosine);
  if (cosine < -1e-12)
    wall = std::min(wall, (low - sensor_x) / cosine);
  if (sine > 1e-12)
    wall = std::min(wall, (high - sensor_y) / sine);
  if (sine < -1e-12)
    wall = std::min(wall, (low - sensor_y) / sine);
  const double slope = std::tan(elevation);
  if (slope < 0.0 && 0.8 / -slope < wall) {
    return 0.8 / -slope / std::cos(elevation);
  }
  return 0.8 + slope * wall <= 2.0 ? wall / std::cos(elevation) : 0.0;
}

struct Revolution {
  std::vector<Vlp16Packet> packets;
  std::vector<Vlp16Return> returns;
};

Revolution simulateRevolution(const World& world)
{
  SimulatorSettings settings;
  Simulator simulator(world, common::VehicleSettings{}, settings);
  simulator.recordReturns(true);
  Revolution revolution;
  for (int step = 0; step < 20; ++step) {
    auto output = simulator.step(0.005);
    revolution.packets.insert(revolution.packets.end(), output.packets.begin(), output.packets.end());
  }
  revolution.returns = simulator.takeReturns();
  // Keep only the returns of complete packets.
  revolution.returns.resize(revolution.packets.size() * kVlp16FiringsPerPacket * kVlp16Lasers);
  return revolution;
}

TEST(Vlp16Scanner, RangesMatchTheRoomGeometry)
{
  const World world = builtinRoom(12.0);
  const Revolution revolution = simulateRevolution(world);
  ASSERT_EQ(revolution.packets.size(), 75u);  // 100 ms of firings, 24 per packet
  const common::VehicleSettings vehicle;
  const double sensor_x = world.start.x + vehicle.lidar_x_m;
  int returns = 0;
  for (const auto& fired : revolution.returns) {
    const double direction = world.start.heading - fired.azimuth_deg * kDegree;
    const double expected =
        roomRange(12.0, sensor_x, world.start.y, direction, kVlp16VerticalAnglesDeg[fired.laser] * kDegree);
    ASSERT_NEAR(fired.slant_distance_m, expected, 0.02)
        << "laser " << fired.laser << " azimuth " << fired.azimuth_deg;
    returns += fired.slant_distance_m > 0.0 ? 1 : 0;
  }
  EXPECT_GT(returns, 20000);
}

TEST(Vlp16Scanner, PacketsDecodeIntoTheCastRanges)
{
  const World world = builtinPushRoom(20.0);
  const Revolution revolution = simulateRevolution(world);
  ASSERT_EQ(revolution.packets.size(), 75u);
  std::vector<velodyne::Point> points;
  std::uint32_t previous_timestamp = 0;
  for (std::size_t index = 0; index < revolution.packets.size(); ++index) {
    const auto result = velodyne::decodePacket(common::ByteView(revolution.packets[index]), points);
    ASSERT_EQ(result.info.status, velodyne::PacketStatus::kOk) << "packet " << index;
    EXPECT_EQ(result.info.return_mode, velodyne::ReturnMode::kStrongest);
    if (index > 0) {
      // 24 firings of 55.296 us apart: 1327.104 us per packet.
      EXPECT_NEAR(static_cast<double>(result.info.device_time_past_hour - previous_timestamp), 1327.104, 1.0);
    }
    previous_timestamp = result.info.device_time_past_hour;
  }
  std::vector<const Vlp16Return*> cast;
  for (const auto& fired : revolution.returns) {
    if (fired.slant_distance_m > 0.0) {
      cast.push_back(&fired);
    }
  }
  ASSERT_EQ(points.size(), cast.size());
  int box_points = 0;
  for (std::size_t index = 0; index < points.size(); ++index) {
    const auto& point = points[index];
    const auto& fired = *cast[index];
    ASSERT_EQ(point.laser, fired.laser);
    ASSERT_NEAR(point.distance, fired.slant_distance_m, 0.0011) << "point " << index;
    EXPECT_EQ(point.reflectivity, fired.reflectivity);
    // The decoder gives all lasers of a firing the firing's azimuth; ours turn on during the firing.
    const double azimuth_error = std::remainder(point.azimuth_degrees - fired.azimuth_deg, 360.0);
    ASSERT_LT(std::abs(azimuth_error), 0.15) << "point " << index;
    const double elevation = kVlp16VerticalAnglesDeg[fired.laser] * kDegree;
    ASSERT_NEAR(point.z, fired.slant_distance_m * std::sin(elevation), 0.002);
    // Sensor frame: x forward, y left; azimuth clockwise from forward.
    const double horizontal = fired.slant_distance_m * std::cos(elevation);
    const double azimuth = point.azimuth_degrees * kDegree;
    ASSERT_NEAR(point.x, horizontal * std::cos(azimuth), 0.002);
    ASSERT_NEAR(point.y, -horizontal * std::sin(azimuth), 0.002);
    box_points += point.reflectivity == 230 ? 1 : 0;
  }
  EXPECT_GT(box_points, 50);
  // Laser 0 (-15 degrees) straight ahead sees the box face 1.0 m ahead of the sensor.
  const auto& first = *cast[0];
  EXPECT_EQ(first.laser, 0);
  EXPECT_NEAR(points[0].distance, 1.0 / std::cos(15.0 * kDegree), 0.002);
  EXPECT_EQ(points[0].reflectivity, 230);
}

}  // namespace
}  // namespace ifar::sim::lidar
