// The decoder and pcap reader on the real VLP-16 capture in ../shared/data (skipped when absent).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/packet_monitor.hpp"
#include "drivers/velodyne/pcap_reader.hpp"
#include "drivers/velodyne/revolution_assembler.hpp"

namespace ifar::velodyne {
namespace {

const std::string kCapture = std::string(IFAR_SHARED_DATA) + "/vlp16/vlp16_strongest_example.pcap";

TEST(VelodyneRealCapture, EveryPacketDecodesAndNoneIsLost)
{
  if (!std::ifstream(kCapture).good()) {
    GTEST_SKIP() << "real capture not found at " << kCapture << " (shared data is not in this checkout)";
  }
  PcapReader reader = PcapReader::open(kCapture);
  ASSERT_EQ(reader.error(), PcapError::kNone);
  UdpDatagram datagram;
  PacketMonitor monitor;
  std::vector<Point> points;
  std::vector<Revolution> revolutions;
  RevolutionAssembler assembler([&](const Revolution& revolution) { revolutions.push_back(revolution); });
  int packets = 0;
  std::size_t total_points = 0;
  PcapRecord record;
  while ((record = reader.next(datagram)) == PcapRecord::kUdpDatagram) {
    ++packets;
    EXPECT_EQ(datagram.destination_port, 2368);
    points.clear();
    const DecodeResult result = decodePacket(datagram.payload, points);
    ASSERT_EQ(result.info.status, PacketStatus::kOk) << "packet " << packets;
    EXPECT_EQ(result.info.return_mode, ReturnMode::kStrongest);
    monitor.recordValid(result.info);
    for (const Point& point : points) {
      ASSERT_GT(point.distance, 0.0F);
      ASSERT_LT(point.distance, 131.0F);
      ASSERT_NEAR(std::hypot(point.x, point.y, point.z), point.distance, 1e-4);
      ASSERT_GE(point.azimuth_degrees, 0.0F);
      ASSERT_LT(point.azimuth_degrees, 360.0F);
    }
    total_points += points.size();
    assembler.add(points, datagram.capture_time_us);
  }
  EXPECT_EQ(record, PcapRecord::kEndOfFile);
  EXPECT_EQ(packets, 84);
  EXPECT_EQ(monitor.counts().dropped_packets, 0);
  EXPECT_GT(total_points, 84U * 384U / 2U);
  // The capture starts at 234.24 degrees and goes once past 360: one cut.
  ASSERT_EQ(revolutions.size(), 1U);
  EXPECT_FLOAT_EQ(revolutions[0].points.front().azimuth_degrees, 234.24F);
  EXPECT_GT(revolutions[0].points.back().azimuth_degrees, 359.0F);
}

}  // namespace
}  // namespace ifar::velodyne
