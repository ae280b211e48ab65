#include "drivers/velodyne/revolution_assembler.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "drivers/velodyne/packet_decoder.hpp"
#include "tests/unit/velodyne/packet_builder.hpp"

namespace ifar::velodyne {
namespace {

Point pointAt(float azimuth_degrees, float time_offset_us = 0.0F)
{
  Point point;
  point.azimuth_degrees = azimuth_degrees;
  point.time_offset_us = time_offset_us;
  return point;
}

TEST(VelodyneRevolutionAssembler, CutsWhereTheAzimuthWraps)
{
  std::vector<Revolution> revolutions;
  RevolutionAssembler assembler([&](const Revolution& revolution) { revolutions.push_back(revolution); });
  const std::vector<Point> first = {pointAt(350.0F), pointAt(355.0F, 10.0F)};
  const std::vector<Point> second = {pointAt(359.9F, 1.0F), pointAt(0.1F, 2.0F), pointAt(4.0F, 3.0F)};
  assembler.add(first, 1'000);
  EXPECT_TRUE(revolutions.empty());
  assembler.add(second, 1'500);
  ASSERT_EQ(revolutions.size(), 1U);
  EXPECT_EQ(revolutions[0].points.size(), 3U);
  EXPECT_EQ(revolutions[0].packet_count, 2U);
  EXPECT_EQ(revolutions[0].start_time_us, 1'000);
  // Times are re-based to the revolution's first packet.
  EXPECT_FLOAT_EQ(revolutions[0].points[1].time_offset_us, 10.0F);
  EXPECT_FLOAT_EQ(revolutions[0].points[2].time_offset_us, 501.0F);
  EXPECT_EQ(assembler.pendingPoints(), 2U);

  assembler.flush();
  ASSERT_EQ(revolutions.size(), 2U);
  EXPECT_EQ(revolutions[1].start_time_us, 1'500);
  EXPECT_EQ(revolutions[1].packet_count, 1U);
  EXPECT_FLOAT_EQ(revolutions[1].points[0].time_offset_us, 2.0F);
  EXPECT_FLOAT_EQ(revolutions[1].points[1].time_offset_us, 3.0F);
  EXPECT_EQ(assembler.pendingPoints(), 0U);
  assembler.flush();
  EXPECT_EQ(revolutions.size(), 2U);  // nothing pending: nothing emitted
}

TEST(VelodyneRevolutionAssembler, SmallBackwardStepsDoNotCut)
{
  int revolutions = 0;
  RevolutionAssembler assembler([&](const Revolution&) { ++revolutions; });
  // Dual return order: last(10.0), last(10.2), strongest(10.0), strongest(10.2), ...
  const std::vector<Point> points = {pointAt(10.0F), pointAt(10.2F), pointAt(10.0F), pointAt(10.2F),
                                     pointAt(9.9F)};
  assembler.add(points, 0);
  EXPECT_EQ(revolutions, 0);
  EXPECT_EQ(assembler.pendingPoints(), 5U);
}

TEST(VelodyneRevolutionAssembler, DecodedPacketsMakeOneRevolutionPerTurn)
{
  std::vector<Revolution> revolutions;
  RevolutionAssembler assembler([&](const Revolution& revolution) { revolutions.push_back(revolution); });
  // 10 Hz: each packet advances 12 * 0.3981 degrees; 76 packets make just over one turn.
  std::vector<Point> points;
  std::uint32_t start = 0;
  for (int packet = 0; packet < 160; ++packet) {
    testing::PacketBuilder builder;
    builder.allReturns(5000, 10).azimuthRamp(static_cast<std::uint16_t>(start % 36000), 40);
    points.clear();
    ASSERT_EQ(decodePacket(common::ByteView(builder.bytes()), points).info.status, PacketStatus::kOk);
    assembler.add(points, packet * 1327);
    start += 480;
  }
  // Turns complete at packets 75 and 150 (36000 / 480 = 75 packets per turn).
  ASSERT_EQ(revolutions.size(), 2U);
  EXPECT_EQ(revolutions[0].packet_count, 75U);
  EXPECT_EQ(revolutions[0].points.size(), 75U * 384U);
  EXPECT_EQ(revolutions[1].packet_count, 75U);
  EXPECT_EQ(revolutions[1].start_time_us, 75 * 1327);
  EXPECT_FLOAT_EQ(revolutions[1].points.front().azimuth_degrees, 0.0F);
}

}  // namespace
}  // namespace ifar::velodyne
