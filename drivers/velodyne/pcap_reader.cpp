#include "drivers/velodyne/pcap_reader.hpp"

#include <array>
#include <fstream>
#include <utility>

#include "common/byte_order.hpp"

namespace ifar::velodyne {
namespace {

constexpr std::size_t kGlobalHeaderSize = 24;
constexpr std::size_t kRecordHeaderSize = 16;
constexpr std::uint32_t kMagicMicroseconds = 0xA1B2C3D4U;
constexpr std::uint32_t kMagicNanoseconds = 0xA1B23C4DU;
constexpr std::uint32_t kLinkTypeEthernet = 1;
// Frames longer than this are not plausible for UDP over Ethernet (jumbo frames included).
constexpr std::uint32_t kMaximumRecordLength = 262144;

constexpr std::size_t kEthernetHeaderSize = 14;
constexpr std::size_t kVlanTagSize = 4;
constexpr std::uint16_t kEtherTypeIpv4 = 0x0800;
constexpr std::uint16_t kEtherTypeVlan = 0x8100;
constexpr std::size_t kMinimumIpv4HeaderSize = 20;
constexpr std::uint8_t kProtocolUdp = 17;
constexpr std::size_t kUdpHeaderSize = 8;

using common::readUint16Be;
using common::readUint32Be;
using common::readUint32Le;

}  // namespace

const char* toString(PcapError error)
{
  switch (error) {
    case PcapError::kNone:
      return "no error";
    case PcapError::kCannotOpen:
      return "cannot open the file";
    case PcapError::kTruncatedHeader:
      return "file is shorter than the 24-byte pcap header";
    case PcapError::kBadMagic:
      return "not a classic pcap file (bad magic number; pcapng is not supported)";
    case PcapError::kUnsupportedLinkType:
      return "link type is not Ethernet";
  }
  return "unknown pcap error";
}

const char* toString(PcapRecord record)
{
  switch (record) {
    case PcapRecord::kUdpDatagram:
      return "udp datagram";
    case PcapRecord::kNotIpv4Udp:
      return "not an IPv4/UDP frame";
    case PcapRecord::kIpv4Fragment:
      return "IPv4 fragment";
    case PcapRecord::kMalformedFrame:
      return "malformed frame";
    case PcapRecord::kCapturedShort:
      return "datagram cut by the capture's snap length";
    case PcapRecord::kTruncatedFile:
      return "file ends inside a record";
    case PcapRecord::kEndOfFile:
      return "end of file";
  }
  return "unknown pcap record";
}

PcapReader PcapReader::open(const std::string& path)
{
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!file->is_open()) {
    return PcapReader(PcapError::kCannotOpen);
  }
  return PcapReader(std::move(file));
}

PcapReader::PcapReader(std::unique_ptr<std::istream> stream) : stream_(std::move(stream))
{
  readGlobalHeader();
}

std::uint32_t PcapReader::fileUint32(const std::uint8_t* bytes) const
{
  return swapped_ ? readUint32Be(bytes) : readUint32Le(bytes);
}

void PcapReader::readGlobalHeader()
{
  std::array<std::uint8_t, kGlobalHeaderSize> header{};
  if (!stream_ || !stream_->read(reinterpret_cast<char*>(header.data()), header.size())) {
    error_ = PcapError::kTruncatedHeader;
    return;
  }
  // The magic number tells the writer's byte order: try little-endian first, then big-endian.
  const std::uint32_t magic = readUint32Le(header.data());
  if (magic == kMagicMicroseconds || magic == kMagicNanoseconds) {
    swapped_ = false;
  } else {
    const std::uint32_t big_endian_magic = readUint32Be(header.data());
    if (big_endian_magic != kMagicMicroseconds && big_endian_magic != kMagicNanoseconds) {
      error_ = PcapError::kBadMagic;
      return;
    }
    swapped_ = true;
  }
  nanosecond_ = fileUint32(header.data()) == kMagicNanoseconds;
  if (fileUint32(header.data() + 20) != kLinkTypeEthernet) {
    error_ = PcapError::kUnsupportedLinkType;
  }
}

PcapRecord PcapReader::next(UdpDatagram& datagram)
{
  if (error_ != PcapError::kNone) {
    return PcapRecord::kEndOfFile;
  }
  if (finished_) {
    return finished_result_;
  }
  const auto finish = [this](PcapRecord result) {
    finished_ = true;
    finished_result_ = result;
    return result;
  };
  std::array<std::uint8_t, kRecordHeaderSize> header{};
  stream_->read(reinterpret_cast<char*>(header.data()), header.size());
  const auto header_bytes = static_cast<std::size_t>(stream_->gcount());
  if (header_bytes == 0) {
    return finish(PcapRecord::kEndOfFile);
  }
  if (header_bytes < header.size()) {
    return finish(PcapRecord::kTruncatedFile);
  }
  const std::uint32_t seconds = fileUint32(header.data());
  const std::uint32_t fraction = fileUint32(header.data() + 4);
  const std::uint32_t captured_length = fileUint32(header.data() + 8);
  const std::uint32_t original_length = fileUint32(header.data() + 12);
  if (captured_length > kMaximumRecordLength) {
    // A length this large means the file is corrupt from here on: nothing after it can be trusted.
    return finish(PcapRecord::kTruncatedFile);
  }
  record_.resize(captured_length);
  stream_->read(reinterpret_cast<char*>(record_.data()), static_cast<std::streamsize>(captured_length));
  if (static_cast<std::uint32_t>(stream_->gcount()) < captured_length) {
    return finish(PcapRecord::kTruncatedFile);
  }
  datagram = UdpDatagram{};
  datagram.capture_time_us = static_cast<std::int64_t>(seconds) * 1'000'000 +
                             static_cast<std::int64_t>(nanosecond_ ? fraction / 1000 : fraction);
  return parseEthernetFrame(common::ByteView(record_.data(), record_.size()), original_length, datagram);
}

PcapRecord parseEthernetFrame(common::ByteView frame, std::uint32_t original_length, UdpDatagram& datagram)
{
  const std::uint8_t* bytes = frame.data();
  std::size_t offset = kEthernetHeaderSize;
  if (frame.size() < offset) {
    return frame.size() < original_length ? PcapRecord::kCapturedShort : PcapRecord::kMalformedFrame;
  }
  std::uint16_t ether_type = readUint16Be(bytes + 12);
  if (ether_type == kEtherTypeVlan) {
    if (frame.size() < offset + kVlanTagSize) {
      return PcapRecord::kMalformedFrame;
    }
    ether_type = readUint16Be(bytes + 16);
    offset += kVlanTagSize;
  }
  if (ether_type != kEtherTypeIpv4) {
    return PcapRecord::kNotIpv4Udp;
  }
  const bool cut_by_snap_length = frame.size() < original_length;
  if (frame.size() < offset + kMinimumIpv4HeaderSize) {
    return cut_by_snap_length ? PcapRecord::kCapturedShort : PcapRecord::kMalformedFrame;
  }
  const std::uint8_t* ip = bytes + offset;
  const std::size_t ip_header_size = static_cast<std::size_t>(ip[0] & 0x0F) * 4;
  if ((ip[0] >> 4) != 4 || ip_header_size < kMinimumIpv4HeaderSize) {
    return PcapRecord::kMalformedFrame;
  }
  if (ip[9] != kProtocolUdp) {
    return PcapRecord::kNotIpv4Udp;
  }
  const std::uint16_t fragment_field = readUint16Be(ip + 6);
  const bool more_fragments = (fragment_field & 0x2000) != 0;
  if (more_fragments || (fragment_field & 0x1FFF) != 0) {
    return PcapRecord::kIpv4Fragment;
  }
  const std::size_t ip_total_length = readUint16Be(ip + 2);
  if (ip_total_length < ip_header_size + kUdpHeaderSize) {
    return PcapRecord::kMalformedFrame;
  }
  const std::size_t available = frame.size() - offset;
  if (available < ip_total_length) {
    return cut_by_snap_length ? PcapRecord::kCapturedShort : PcapRecord::kMalformedFrame;
  }
  const std::uint8_t* udp = ip + ip_header_size;
  const std::size_t udp_length = readUint16Be(udp + 4);
  if (udp_length < kUdpHeaderSize || udp_length > ip_total_length - ip_header_size) {
    return PcapRecord::kMalformedFrame;
  }
  datagram.source_address = readUint32Be(ip + 12);
  datagram.destination_address = readUint32Be(ip + 16);
  datagram.source_port = readUint16Be(udp);
  datagram.destination_port = readUint16Be(udp + 2);
  datagram.payload = common::ByteView(udp + kUdpHeaderSize, udp_length - kUdpHeaderSize);
  return PcapRecord::kUdpDatagram;
}

}  // namespace ifar::velodyne
