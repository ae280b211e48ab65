#include "drivers/velodyne/pcap_reader.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace ifar::velodyne {
namespace {

// Writes pcap files byte by byte in either byte order, independent of the reader.
class PcapWriter {
 public:
  PcapWriter(bool big_endian, bool nanosecond, std::uint32_t link_type = 1) : big_endian_(big_endian)
  {
    put32(nanosecond ? 0xA1B23C4DU : 0xA1B2C3D4U);
    put16(2);
    put16(4);
    put32(0);
    put32(0);
    put32(65535);
    put32(link_type);
  }

  void record(std::uint32_t seconds, std::uint32_t fraction, const std::vector<std::uint8_t>& frame,
              std::uint32_t original_length = 0)
  {
    put32(seconds);
    put32(fraction);
    put32(static_cast<std::uint32_t>(frame.size()));
    put32(original_length == 0 ? static_cast<std::uint32_t>(frame.size()) : original_length);
    bytes_.insert(bytes_.end(), frame.begin(), frame.end());
  }

  std::string text() const { return std::string(bytes_.begin(), bytes_.end()); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  void put16(std::uint16_t value)
  {
    if (big_endian_) {
      bytes_.push_back(static_cast<std::uint8_t>(value >> 8));
      bytes_.push_back(static_cast<std::uint8_t>(value));
    } else {
      bytes_.push_back(static_cast<std::uint8_t>(value));
      bytes_.push_back(static_cast<std::uint8_t>(value >> 8));
    }
  }
  void put32(std::uint32_t value)
  {
    for (int index = 0; index < 4; ++index) {
      const int shift = big_endian_ ? 24 - 8 * index : 8 * index;
      bytes_.push_back(static_cast<std::uint8_t>(value >> shift));
    }
  }

  bool big_endian_;
  std::vector<std::uint8_t> bytes_;
};

// Ethernet + IPv4 (20-byte header) + UDP around `payload`; network byte order.
std::vector<std::uint8_t> udpFrame(std::uint16_t source_port, std::uint16_t destination_port,
                                   const std::vector<std::uint8_t>& payload, std::uint8_t protocol = 17,
                                   std::uint16_t fragment_field = 0x4000)
{
  std::vector<std::uint8_t> frame(14, 0xAA);
  frame[12] = 0x08;
  frame[13] = 0x00;
  const std::size_t ip_length = 20 + 8 + payload.size();
  const std::uint8_t ip[20] = {0x45,
                               0,
                               static_cast<std::uint8_t>(ip_length >> 8),
                               static_cast<std::uint8_t>(ip_length),
                               0,
                               0,
                               static_cast<std::uint8_t>(fragment_field >> 8),
                               static_cast<std::uint8_t>(fragment_field),
                               64,
                               protocol,
                               0,
                               0,
                               192,
                               168,
                               1,
                               201,
                               255,
                               255,
                               255,
                               255};
  frame.insert(frame.end(), ip, ip + 20);
  const std::size_t udp_length = 8 + payload.size();
  const std::uint8_t udp[8] = {static_cast<std::uint8_t>(source_port >> 8),
                               static_cast<std::uint8_t>(source_port),
                               static_cast<std::uint8_t>(destination_port >> 8),
                               static_cast<std::uint8_t>(destination_port),
                               static_cast<std::uint8_t>(udp_length >> 8),
                               static_cast<std::uint8_t>(udp_length),
                               0,
                               0};
  frame.insert(frame.end(), udp, udp + 8);
  frame.insert(frame.end(), payload.begin(), payload.end());
  return frame;
}

PcapReader readerOf(const std::string& text)
{
  return PcapReader(std::make_unique<std::istringstream>(text));
}

class PcapByteOrder : public ::testing::TestWithParam<bool> {};

TEST_P(PcapByteOrder, ReadsUdpPayloadsAndTimestamps)
{
  const bool big_endian = GetParam();
  PcapWriter writer(big_endian, false);
  writer.record(1'525'347'606, 362'040, udpFrame(2368, 2368, {1, 2, 3, 4, 5}));
  writer.record(1'525'347'607, 5, udpFrame(8308, 8308, {9}));
  PcapReader reader = readerOf(writer.text());
  ASSERT_EQ(reader.error(), PcapError::kNone);
  EXPECT_EQ(reader.swappedByteOrder(), big_endian);
  EXPECT_FALSE(reader.nanosecondTimestamps());

  UdpDatagram datagram;
  ASSERT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
  EXPECT_EQ(datagram.capture_time_us, 1'525'347'606'362'040LL);
  EXPECT_EQ(datagram.source_port, 2368);
  EXPECT_EQ(datagram.destination_port, 2368);
  EXPECT_EQ(datagram.source_address, 0xC0A801C9U);  // 192.168.1.201
  EXPECT_EQ(datagram.destination_address, 0xFFFFFFFFU);
  EXPECT_EQ(std::vector<std::uint8_t>(datagram.payload.begin(), datagram.payload.end()),
            (std::vector<std::uint8_t>{1, 2, 3, 4, 5}));
  ASSERT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
  EXPECT_EQ(datagram.capture_time_us, 1'525'347'607'000'005LL);
  EXPECT_EQ(datagram.destination_port, 8308);
  EXPECT_EQ(datagram.payload.size(), 1U);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kEndOfFile);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kEndOfFile);
}

INSTANTIATE_TEST_SUITE_P(VelodynePcap, PcapByteOrder, ::testing::Values(false, true));

TEST(VelodynePcap, NanosecondTimestamps)
{
  PcapWriter writer(false, true);
  writer.record(10, 123'456'789, udpFrame(1, 2, {7}));
  PcapReader reader = readerOf(writer.text());
  EXPECT_TRUE(reader.nanosecondTimestamps());
  UdpDatagram datagram;
  ASSERT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
  EXPECT_EQ(datagram.capture_time_us, 10'123'456LL);
}

TEST(VelodynePcap, FileLevelErrors)
{
  EXPECT_EQ(PcapReader::open("/nonexistent/capture.pcap").error(), PcapError::kCannotOpen);
  EXPECT_EQ(readerOf("short").error(), PcapError::kTruncatedHeader);
  EXPECT_EQ(readerOf(std::string(24, 'x')).error(), PcapError::kBadMagic);
  EXPECT_EQ(readerOf(PcapWriter(false, false, 113).text()).error(), PcapError::kUnsupportedLinkType);
  PcapReader bad = readerOf("short");
  UdpDatagram datagram;
  EXPECT_EQ(bad.next(datagram), PcapRecord::kEndOfFile);
  EXPECT_STREQ(toString(PcapError::kBadMagic),
               "not a classic pcap file (bad magic number; pcapng is not supported)");
}

TEST(VelodynePcap, SkipsWhatIsNotIpv4UdpAndKeepsGoing)
{
  PcapWriter writer(false, false);
  auto arp = udpFrame(1, 2, {1});
  arp[12] = 0x08;
  arp[13] = 0x06;
  writer.record(1, 0, arp);
  writer.record(1, 1, udpFrame(1, 2, {1}, 6));           // TCP
  writer.record(1, 2, udpFrame(1, 2, {1}, 17, 0x2000));  // first fragment
  auto bad_udp_length = udpFrame(1, 2, {1, 2});
  bad_udp_length[14 + 20 + 5] = 200;  // UDP length beyond the IP packet
  writer.record(1, 3, bad_udp_length);
  auto cut = udpFrame(1, 2, std::vector<std::uint8_t>(100, 1));
  const auto original = static_cast<std::uint32_t>(cut.size());
  cut.resize(60);
  writer.record(1, 4, cut, original);  // snap length cut the datagram
  writer.record(1, 5, {1, 2, 3});      // runt frame
  writer.record(1, 6, udpFrame(1, 2368, {42}));
  PcapReader reader = readerOf(writer.text());
  UdpDatagram datagram;
  EXPECT_EQ(reader.next(datagram), PcapRecord::kNotIpv4Udp);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kNotIpv4Udp);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kIpv4Fragment);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kMalformedFrame);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kCapturedShort);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kMalformedFrame);
  ASSERT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
  EXPECT_EQ(datagram.payload[0], 42);
  EXPECT_EQ(reader.next(datagram), PcapRecord::kEndOfFile);
}

TEST(VelodynePcap, VlanTaggedFrame)
{
  auto frame = udpFrame(5, 2368, {7, 8});
  const std::uint8_t tag[4] = {0x81, 0x00, 0x00, 0x05};
  frame.insert(frame.begin() + 12, tag, tag + 4);
  PcapWriter writer(false, false);
  writer.record(1, 0, frame);
  PcapReader reader = readerOf(writer.text());
  UdpDatagram datagram;
  ASSERT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
  EXPECT_EQ(datagram.destination_port, 2368);
  EXPECT_EQ(datagram.payload.size(), 2U);
}

TEST(VelodynePcap, TruncatedRecordsAreReported)
{
  PcapWriter writer(false, false);
  writer.record(1, 0, udpFrame(1, 2368, {1, 2, 3}));
  writer.record(1, 1, udpFrame(1, 2368, {4, 5, 6}));
  const std::string whole = writer.text();
  // Cut inside the second record's body, then inside its header.
  for (const std::size_t cut : {whole.size() - 2, whole.size() - 3 - 8 - 20 - 14 - 10}) {
    PcapReader reader = readerOf(whole.substr(0, cut));
    UdpDatagram datagram;
    EXPECT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
    EXPECT_EQ(reader.next(datagram), PcapRecord::kTruncatedFile) << "cut at " << cut;
    EXPECT_EQ(reader.next(datagram), PcapRecord::kTruncatedFile);
  }
}

TEST(VelodynePcap, AbsurdRecordLengthStopsReading)
{
  PcapWriter writer(false, false);
  writer.record(1, 0, udpFrame(1, 2368, {1}));
  auto& bytes = writer.bytes();
  bytes[24 + 8 + 3] = 0x7F;  // captured length 0x7F0000xx
  PcapReader reader = readerOf(writer.text());
  UdpDatagram datagram;
  EXPECT_EQ(reader.next(datagram), PcapRecord::kTruncatedFile);
}

}  // namespace
}  // namespace ifar::velodyne
