#include "drivers/velodyne/pcap_reader.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "tests/unit/velodyne/capture_writers.hpp"

namespace ifar::velodyne {
namespace {

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
  EXPECT_EQ(reader.linkType(), 1);

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
  ASSERT_EQ(reader.error(), PcapError::kNone);
  UdpDatagram datagram;
  ASSERT_EQ(reader.next(datagram), PcapRecord::kUdpDatagram);
  EXPECT_EQ(datagram.capture_time_us, 10'123'456LL);
}

TEST(VelodynePcap, FileLevelErrors)
{
  EXPECT_EQ(PcapReader::open("/nonexistent/capture.pcap").error(), PcapError::kCannotOpen);
  EXPECT_EQ(readerOf("short").error(), PcapError::kTruncatedHeader);
  EXPECT_EQ(readerOf(std::string(24, 'x')).error(), PcapError::kBadMagic);
  const PcapReader wifi = readerOf(PcapWriter(false, false, 105).text());
  EXPECT_EQ(wifi.error(), PcapError::kUnsupportedLinkType);
  EXPECT_EQ(wifi.errorText(),
            "link type is not Ethernet, Linux cooked (SLL, SLL2), raw IPv4 or loopback: link type 105 "
            "(IEEE802_11)");
  PcapReader bad = readerOf("short");
  UdpDatagram datagram;
  EXPECT_EQ(bad.next(datagram), PcapRecord::kEndOfFile);
  EXPECT_EQ(bad.errorText(), "file is shorter than the 24-byte pcap header");
  EXPECT_STREQ(toString(PcapError::kBadMagic), "not a pcap or pcapng capture (bad magic number)");
  // A pcapng magic number with a section header libpcap refuses: its words are passed on.
  std::string broken_section(32, '\0');
  broken_section.replace(0, 4, "\x0A\x0D\x0D\x0A");
  const PcapReader refused = readerOf(broken_section);
  EXPECT_EQ(refused.error(), PcapError::kUnreadable);
  EXPECT_EQ(refused.errorText().rfind("libpcap cannot read the capture: ", 0), 0U) << refused.errorText();
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

/// Every datagram of a capture: destination port, capture time and payload, until the reader stops.
struct Read {
  std::vector<std::tuple<std::uint16_t, std::int64_t, std::vector<std::uint8_t>>> datagrams;
  std::vector<PcapRecord> skipped;
  PcapRecord last = PcapRecord::kEndOfFile;
};
Read readAll(PcapReader reader)
{
  Read read;
  UdpDatagram datagram;
  while (true) {
    const PcapRecord record = reader.next(datagram);
    if (record == PcapRecord::kUdpDatagram) {
      read.datagrams.emplace_back(
          datagram.destination_port, datagram.capture_time_us,
          std::vector<std::uint8_t>(datagram.payload.begin(), datagram.payload.end()));
    } else if (record == PcapRecord::kEndOfFile || record == PcapRecord::kTruncatedFile) {
      read.last = record;
      return read;
    } else {
      read.skipped.push_back(record);
    }
  }
}

TEST(VelodynePcap, PcapngGivesTheSameDatagramsAsPcap)
{
  PcapWriter classic(false, false);
  PcapngWriter next_generation(1);
  const std::vector<std::uint8_t> arp(60, 0x06);
  std::vector<std::uint8_t> arp_frame = udpFrame(1, 2, {});
  arp_frame[12] = 0x08;
  arp_frame[13] = 0x06;
  for (int index = 0; index < 3; ++index) {
    const auto frame = udpFrame(2368, 2368, {static_cast<std::uint8_t>(index), 2, 3});
    classic.record(1'525'347'606, 362'040 + index, frame);
    next_generation.packet(1'525'347'606'362'040ULL + index, frame);
  }
  classic.record(1'525'347'607, 0, arp_frame);
  next_generation.packet(1'525'347'607'000'000ULL, arp_frame);
  PcapReader pcapng = readerOf(next_generation.text());
  ASSERT_EQ(pcapng.error(), PcapError::kNone) << pcapng.errorText();
  const Read expected = readAll(readerOf(classic.text()));
  const Read read = readAll(std::move(pcapng));
  ASSERT_EQ(expected.datagrams.size(), 3U);
  EXPECT_EQ(read.datagrams, expected.datagrams);
  EXPECT_EQ(read.skipped, (std::vector<PcapRecord>{PcapRecord::kNotIpv4Udp}));
  EXPECT_EQ(read.last, PcapRecord::kEndOfFile);
}

TEST(VelodynePcap, PcapngNanosecondInterfaceTimestamps)
{
  PcapngWriter writer(1, true);
  writer.packet(10'123'456'789ULL, udpFrame(1, 2368, {7}));
  const Read read = readAll(readerOf(writer.text()));
  ASSERT_EQ(read.datagrams.size(), 1U);
  EXPECT_EQ(std::get<1>(read.datagrams.front()), 10'123'456LL);
}

TEST(VelodynePcap, LinuxCookedRawAndLoopbackCaptures)
{
  const auto ethernet = udpFrame(2368, 2368, {4, 5, 6});
  const std::vector<std::uint8_t> payload = {4, 5, 6};
  const std::vector<std::uint8_t> ip(ethernet.begin() + 14, ethernet.end());
  std::vector<std::uint8_t> loopback = {2, 0, 0, 0};  // AF_INET, little-endian host
  loopback.insert(loopback.end(), ip.begin(), ip.end());
  std::vector<std::uint8_t> ipv6_cooked = cookedFrame(ethernet, false);
  ipv6_cooked[14] = 0x86;
  ipv6_cooked[15] = 0xDD;
  std::vector<std::uint8_t> ipv6_raw = ip;
  ipv6_raw[0] = 0x60;
  const struct {
    std::uint32_t link_type;
    std::vector<std::vector<std::uint8_t>> frames;
    std::vector<PcapRecord> skipped;
  } captures[] = {
      {113, {cookedFrame(ethernet, false), ipv6_cooked}, {PcapRecord::kNotIpv4Udp}},
      {276, {cookedFrame(ethernet, true)}, {}},
      {101, {ip, ipv6_raw}, {PcapRecord::kNotIpv4Udp}},
      {228, {ip}, {}},
      {0, {loopback}, {}},
  };
  for (const auto& capture : captures) {
    PcapWriter writer(false, false, capture.link_type);
    for (const auto& frame : capture.frames) {
      writer.record(5, 6, frame);
    }
    PcapReader reader = readerOf(writer.text());
    ASSERT_EQ(reader.error(), PcapError::kNone)
        << "link type " << capture.link_type << ": " << reader.errorText();
    const Read read = readAll(std::move(reader));
    ASSERT_EQ(read.datagrams.size(), 1U) << "link type " << capture.link_type;
    EXPECT_EQ(std::get<0>(read.datagrams.front()), 2368);
    EXPECT_EQ(std::get<1>(read.datagrams.front()), 5'000'006LL);
    EXPECT_EQ(std::get<2>(read.datagrams.front()), payload);
    EXPECT_EQ(read.skipped, capture.skipped) << "link type " << capture.link_type;
  }
}

TEST(VelodynePcap, CookedHeaderCutShortIsReported)
{
  PcapWriter writer(false, false, 113);
  const auto cooked = cookedFrame(udpFrame(2368, 2368, {1}), false);
  writer.record(1, 0, std::vector<std::uint8_t>(cooked.begin(), cooked.begin() + 10),
                static_cast<std::uint32_t>(cooked.size()));
  writer.record(1, 1, std::vector<std::uint8_t>(cooked.begin(), cooked.begin() + 10));
  const Read read = readAll(readerOf(writer.text()));
  EXPECT_EQ(read.skipped, (std::vector<PcapRecord>{PcapRecord::kCapturedShort, PcapRecord::kMalformedFrame}));
}

}  // namespace
}  // namespace ifar::velodyne
