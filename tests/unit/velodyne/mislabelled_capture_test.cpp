// The real VLP-16 capture with its product bytes relabelled 0x21 (as a second real capture came): refused,
// naming both bytes, unless sensor_model says VLP-16; then the same points as the capture as it was, and
// the same packets published. Also --points on it. Skipped when ../shared/data is absent.

#include <gtest/gtest.h>

#include <spdlog/sinks/ostream_sink.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/velodyne/capture_points.hpp"
#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/packet_forwarder.hpp"
#include "drivers/velodyne/pcap_reader.hpp"

namespace ifar::velodyne {
namespace {

const std::string kCapture = std::string(IFAR_SHARED_DATA) + "/vlp16/vlp16_strongest_example.pcap";
constexpr std::size_t kPackets = 84;
const std::string kRefusal =
    "data packet (1206 bytes): product byte 0x21 (expected 0x22, VLP-16); set sensor_model: VLP-16 to decode "
    "it "
    "anyway";

std::vector<char> readFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

/// The data payloads of a pcap held in memory.
std::vector<std::vector<std::uint8_t>> payloads(const std::vector<char>& pcap)
{
  PcapReader reader(std::make_unique<std::istringstream>(std::string(pcap.begin(), pcap.end())));
  std::vector<std::vector<std::uint8_t>> out;
  UdpDatagram datagram;
  while (reader.next(datagram) == PcapRecord::kUdpDatagram) {
    out.emplace_back(datagram.payload.begin(), datagram.payload.end());
  }
  return out;
}

/// The capture with every data packet's product byte (the payload's last byte) set to `product`.
std::vector<char> relabelled(std::vector<char> pcap, std::uint8_t product)
{
  constexpr std::size_t kGlobalHeader = 24;
  constexpr std::size_t kRecordHeader = 16;
  constexpr std::size_t kEthernetIpUdp = 42;
  std::size_t offset = kGlobalHeader;
  while (offset + kRecordHeader <= pcap.size()) {
    std::uint32_t length = 0;
    for (int index = 3; index >= 0; --index) {
      length = (length << 8) | static_cast<std::uint8_t>(pcap[offset + 8 + static_cast<std::size_t>(index)]);
    }
    if (length == kEthernetIpUdp + kDataPacketSize) {
      pcap[offset + kRecordHeader + kEthernetIpUdp + kProductIdOffset] = static_cast<char>(product);
    }
    offset += kRecordHeader + length;
  }
  return pcap;
}

struct CapturedLog {
  std::ostringstream text;
  std::shared_ptr<spdlog::logger> logger;
  CapturedLog()
      : logger(std::make_shared<spdlog::logger>("velodyne_test",
                                                std::make_shared<spdlog::sinks::ostream_sink_st>(text)))
  {
    logger->set_pattern("%l %v");
  }
  std::size_t count(const std::string& needle) const
  {
    const std::string all = text.str();
    std::size_t found = 0;
    for (std::size_t at = all.find(needle); at != std::string::npos; at = all.find(needle, at + 1)) {
      ++found;
    }
    return found;
  }
};

class VelodyneMislabelledCapture : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (!std::ifstream(kCapture).good()) {
      GTEST_SKIP() << "real capture not found at " << kCapture << " (shared data is not in this checkout)";
    }
    original_ = payloads(readFile(kCapture));
    patched_pcap_ = relabelled(readFile(kCapture), 0x21);
    patched_ = payloads(patched_pcap_);
    ASSERT_EQ(original_.size(), kPackets);
    ASSERT_EQ(patched_.size(), kPackets);
    ASSERT_EQ(original_[0][kProductIdOffset], 0x22);
    ASSERT_EQ(patched_[0][kProductIdOffset], 0x21);
  }

  /// The patched capture in a file of its own, removed at the end of the test.
  std::string patchedFile()
  {
    const std::string path = ::testing::TempDir() + "vlp16_product_0x21.pcap";
    std::ofstream(path, std::ios::binary)
        .write(patched_pcap_.data(), static_cast<std::streamsize>(patched_pcap_.size()));
    temporaries_.push_back(path);
    return path;
  }
  std::string temporary(const std::string& name)
  {
    temporaries_.push_back(::testing::TempDir() + name);
    return temporaries_.back();
  }
  void TearDown() override
  {
    for (const std::string& path : temporaries_) {
      std::remove(path.c_str());
    }
  }

  std::vector<std::vector<std::uint8_t>> original_;
  std::vector<std::vector<std::uint8_t>> patched_;
  std::vector<char> patched_pcap_;
  std::vector<std::string> temporaries_;
};

TEST_F(VelodyneMislabelledCapture, WithoutAModelEveryPacketIsRefusedNamingBothBytes)
{
  CapturedLog log;
  PacketForwarder forwarder(DriverSettings{}, log.logger);
  for (const auto& payload : patched_) {
    std::vector<Point> points;
    const DecodeResult result = decodePacket(common::ByteView(payload), points);
    EXPECT_EQ(result.info.status, PacketStatus::kUnknownProduct);
    EXPECT_TRUE(points.empty());
    EXPECT_FALSE(forwarder.onDatagram(kDataPort, common::ByteView(payload), 1).has_value());
  }
  EXPECT_EQ(forwarder.monitor().counts().bad_packets, static_cast<std::int64_t>(kPackets));
  EXPECT_EQ(forwarder.monitor().counts().packets_valid, 0);
  EXPECT_EQ(forwarder.statusReport(1.0, 2).last_error, kRefusal);
  EXPECT_EQ(log.count(kRefusal), 1U) << log.text.str();  // rate limited: one line, not 84
}

TEST_F(VelodyneMislabelledCapture, ConfiguredAsVlp16ItDecodesToExactlyTheOriginalPoints)
{
  DecoderOptions vlp16;
  vlp16.sensor_model = SensorModel::kVlp16;
  std::size_t total = 0;
  for (std::size_t packet = 0; packet < kPackets; ++packet) {
    std::vector<Point> expected;
    std::vector<Point> points;
    ASSERT_EQ(decodePacket(common::ByteView(original_[packet]), expected).info.status, PacketStatus::kOk);
    const DecodeResult result = decodePacket(common::ByteView(patched_[packet]), points, vlp16);
    ASSERT_EQ(result.info.status, PacketStatus::kOk) << "packet " << packet;
    EXPECT_TRUE(result.info.product_overridden);
    EXPECT_EQ(result.info.product_byte, 0x21);
    ASSERT_EQ(points.size(), expected.size()) << "packet " << packet;
    for (std::size_t index = 0; index < points.size(); ++index) {
      const Point& a = points[index];
      const Point& b = expected[index];
      ASSERT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z && a.distance == b.distance &&
                  a.azimuth_degrees == b.azimuth_degrees && a.time_offset_us == b.time_offset_us &&
                  a.reflectivity == b.reflectivity && a.ring == b.ring && a.laser == b.laser &&
                  a.return_index == b.return_index && a.return_type == b.return_type)
          << "packet " << packet << " point " << index;
    }
    total += points.size();
  }
  EXPECT_EQ(total, 31630U);
}

TEST_F(VelodyneMislabelledCapture, ConfiguredAsVlp16TheDriverPublishesItAsVlp16AndWarnsOnce)
{
  DriverSettings settings;
  settings.sensor_model = SensorModel::kVlp16;
  CapturedLog log;
  PacketForwarder forwarder(settings, log.logger);
  for (std::size_t packet = 0; packet < kPackets; ++packet) {
    const auto forwarded = forwarder.onDatagram(kDataPort, common::ByteView(patched_[packet]), 1);
    ASSERT_TRUE(forwarded.has_value()) << "packet " << packet;
    // Relabelled 0x22, so consumers decoding with the strict default take it: byte for byte the original.
    EXPECT_EQ(forwarded->packet.data, original_[packet]) << "packet " << packet;
  }
  EXPECT_EQ(forwarder.monitor().counts().bad_packets, 0);
  EXPECT_EQ(
      log.count("warning data packets carry product byte 0x21 (HDL-32E), not 0x22: decoding them as "
                "VLP-16 because sensor_model says so; if the sensor is not a VLP-16 its points are wrong"),
      1U)
      << log.text.str();
}

TEST_F(VelodyneMislabelledCapture, PointsCommandWritesEveryPointAsCsv)
{
  DriverSettings settings;
  settings.sensor_model = SensorModel::kVlp16;
  CapturedLog log;
  const std::string out = temporary("vlp16_points.csv");
  ASSERT_EQ(writeCapturePoints(patchedFile(), out, settings, log.logger), 0) << log.text.str();
  std::ifstream file(out);
  std::vector<std::string> rows;
  for (std::string line; std::getline(file, line);) {
    rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), 1U + 31630U);
  EXPECT_EQ(rows[0], "x,y,z,intensity,ring,azimuth,distance,return_index,time_us");
  // Block 0, laser 0 of the first packet: raw distance 2392 (4.784 m), reflectivity 48, azimuth 23424,
  // elevation -15 degrees, packet timestamp 596380001 us; x, y, z worked out by hand as floats.
  EXPECT_EQ(rows[1], "-2.700466,3.7498033,-1.2381903,48,0,234.24,4.784,0,596380001.000");
}

TEST_F(VelodyneMislabelledCapture, PointsCommandWritesPcdWithTheCountInItsHeader)
{
  DriverSettings settings;
  settings.sensor_model = SensorModel::kVlp16;
  CapturedLog log;
  const std::string out = temporary("vlp16_points.pcd");
  ASSERT_EQ(writeCapturePoints(patchedFile(), out, settings, log.logger), 0) << log.text.str();
  std::ifstream file(out);
  std::vector<std::string> rows;
  for (std::string line; std::getline(file, line);) {
    rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), 11U + 31630U);
  EXPECT_EQ(rows[6], "WIDTH 31630               ");
  EXPECT_EQ(rows[9], "POINTS 31630               ");
  EXPECT_EQ(rows[10], "DATA ascii");
  EXPECT_EQ(rows[11], "-2.700466 3.7498033 -1.2381903 48 0 234.24 4.784 0 596380001.000");
}

TEST_F(VelodyneMislabelledCapture, PointsCommandFailsWhenEveryPacketIsRefused)
{
  CapturedLog log;
  EXPECT_EQ(writeCapturePoints(patchedFile(), temporary("refused.csv"), DriverSettings{}, log.logger), 1);
  EXPECT_EQ(
      log.count(
          "gave no packet to publish: 84 records read, 0 of them not UDP to port 2368, 84 refused (84 x " +
          kRefusal + ")"),
      1U)
      << log.text.str();
}

}  // namespace
}  // namespace ifar::velodyne
