#include "drivers/velodyne/pcap_reader.hpp"

#include <pcap/pcap.h>

#include <array>
#include <cstring>
#include <utility>

#include "common/byte_order.hpp"

namespace ifar::velodyne {
namespace {

// The smallest capture file header: classic pcap's 24 bytes (a pcapng section header block is longer).
constexpr std::size_t kFileHeaderSize = 24;
constexpr std::uint32_t kMagicMicroseconds = 0xA1B2C3D4U;
constexpr std::uint32_t kMagicNanoseconds = 0xA1B23C4DU;
constexpr std::uint32_t kMagicPcapng = 0x0A0D0D0AU;  // a pcapng section header block, either byte order
// Frames longer than this are not plausible for UDP over Ethernet (jumbo frames included).
constexpr std::uint32_t kMaximumRecordLength = 262144;

constexpr std::size_t kEthernetHeaderSize = 14;
constexpr std::size_t kVlanTagSize = 4;
constexpr std::size_t kSllHeaderSize = 16;  // packet type, ARPHRD, address length, address[8], protocol
constexpr std::size_t kSll2HeaderSize =
    20;  // protocol, reserved, interface, ARPHRD, type, length, address[8]
constexpr std::size_t kLoopbackHeaderSize = 4;
constexpr std::uint32_t kAddressFamilyInet = 2;
constexpr std::uint16_t kEtherTypeIpv4 = 0x0800;
constexpr std::uint16_t kEtherTypeVlan = 0x8100;
constexpr std::size_t kMinimumIpv4HeaderSize = 20;
constexpr std::uint8_t kProtocolUdp = 17;
constexpr std::size_t kUdpHeaderSize = 8;

using common::readUint16Be;
using common::readUint32Be;
using common::readUint32Le;

void closeHandle(pcap* handle)
{
  if (handle != nullptr) {
    pcap_close(handle);
  }
}

bool takenApart(int link_type)
{
  switch (link_type) {
    case DLT_NULL:        // BSD loopback: a 4-byte address family in the capturing host's byte order
    case DLT_EN10MB:      // Ethernet II, optionally 802.1Q tagged
    case DLT_RAW:         // a bare IP packet
    case DLT_LOOP:        // OpenBSD loopback: the address family in network byte order
    case DLT_LINUX_SLL:   // Linux cooked capture v1 (16-byte header)
    case DLT_IPV4:        // a bare IPv4 packet
    case DLT_LINUX_SLL2:  // Linux cooked capture v2 (20-byte header)
      return true;
    default:
      return false;
  }
}

/// How the link-layer header named the packet that follows it.
enum class Announced : std::uint8_t {
  kIpv4,     // its protocol field says IPv4: another IP version is a malformed frame
  kAnyIp,    // a raw-IP capture: IPv6 is just not IPv4
  kNotIpv4,  // ARP, IPv6, ...
};

/// The UDP payload of the IPv4 packet `packet` (what follows the link-layer header in a frame);
/// `cut_by_snap_length` when the capture kept less of the frame than was on the wire.
PcapRecord parseIpv4Packet(common::ByteView packet, bool cut_by_snap_length, Announced announced,
                           UdpDatagram& datagram)
{
  if (packet.size() < kMinimumIpv4HeaderSize) {
    return cut_by_snap_length ? PcapRecord::kCapturedShort : PcapRecord::kMalformedFrame;
  }
  const std::uint8_t* ip = packet.data();
  const std::size_t ip_header_size = static_cast<std::size_t>(ip[0] & 0x0F) * 4;
  if ((ip[0] >> 4) != 4) {
    return announced == Announced::kAnyIp ? PcapRecord::kNotIpv4Udp : PcapRecord::kMalformedFrame;
  }
  if (ip_header_size < kMinimumIpv4HeaderSize) {
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
  if (packet.size() < ip_total_length) {
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

/// The IPv4 packet after a link-layer header of `header_size` bytes that announced it.
PcapRecord parseAfterHeader(common::ByteView frame, std::uint32_t original_length, std::size_t header_size,
                            Announced announced, UdpDatagram& datagram)
{
  if (frame.size() < header_size) {
    return frame.size() < original_length ? PcapRecord::kCapturedShort : PcapRecord::kMalformedFrame;
  }
  if (announced == Announced::kNotIpv4) {
    return PcapRecord::kNotIpv4Udp;
  }
  return parseIpv4Packet(common::ByteView(frame.data() + header_size, frame.size() - header_size),
                         frame.size() < original_length, announced, datagram);
}

/// kIpv4 when `is_ipv4`, else kNotIpv4.
Announced announcedBy(bool is_ipv4)
{
  return is_ipv4 ? Announced::kIpv4 : Announced::kNotIpv4;
}

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
      return "not a pcap or pcapng capture (bad magic number)";
    case PcapError::kUnsupportedLinkType:
      return "link type is not Ethernet, Linux cooked (SLL, SLL2), raw IPv4 or loopback";
    case PcapError::kUnreadable:
      return "libpcap cannot read the capture";
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
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    return PcapReader(PcapError::kCannotOpen);
  }
  std::vector<std::uint8_t> first(kFileHeaderSize);
  first.resize(std::fread(first.data(), 1, first.size(), file));
  if (std::fseek(file, 0, SEEK_SET) != 0) {
    std::fclose(file);
    return PcapReader(PcapError::kCannotOpen);
  }
  PcapReader reader(PcapError::kNone);
  reader.openWith(file, first);
  // openWith closes the file or hands it to libpcap, which closes it with the handle.
  return reader;  // NOLINT(clang-analyzer-unix.Stream)
}

PcapReader::PcapReader(std::unique_ptr<std::istream> stream)
{
  std::array<char, 65536> chunk{};
  while (stream && stream->read(chunk.data(), chunk.size()).gcount() > 0) {
    memory_.insert(memory_.end(), chunk.data(), chunk.data() + stream->gcount());
  }
  const std::size_t shown = std::min(memory_.size(), kFileHeaderSize);
  const std::vector<std::uint8_t> first(memory_.begin(),
                                        memory_.begin() + static_cast<std::ptrdiff_t>(shown));
  std::FILE* file = memory_.empty() ? nullptr : fmemopen(memory_.data(), memory_.size(), "rb");
  if (file == nullptr) {
    error_ = memory_.empty() ? PcapError::kTruncatedHeader : PcapError::kCannotOpen;
    return;
  }
  openWith(file, first);
}

PcapReader::~PcapReader() = default;
PcapReader::PcapReader(PcapReader&& other) noexcept = default;
PcapReader& PcapReader::operator=(PcapReader&& other) noexcept = default;

void PcapReader::openWith(std::FILE* file, const std::vector<std::uint8_t>& first_bytes)
{
  // The size and magic number first, so a file that is no capture at all is named as such.
  if (first_bytes.size() < kFileHeaderSize) {
    std::fclose(file);
    error_ = PcapError::kTruncatedHeader;
    return;
  }
  const std::uint32_t little = readUint32Le(first_bytes.data());
  const std::uint32_t big = readUint32Be(first_bytes.data());
  const bool classic = little == kMagicMicroseconds || little == kMagicNanoseconds ||
                       big == kMagicMicroseconds || big == kMagicNanoseconds;
  if (!classic && little != kMagicPcapng) {
    std::fclose(file);
    error_ = PcapError::kBadMagic;
    return;
  }
  std::array<char, PCAP_ERRBUF_SIZE> message{};
  // Nanosecond precision: every file's timestamps as finely as it has them, cut to microseconds below.
  pcap* handle = pcap_fopen_offline_with_tstamp_precision(file, PCAP_TSTAMP_PRECISION_NANO, message.data());
  if (handle == nullptr) {  // libpcap has closed the file
    error_ = PcapError::kUnreadable;
    detail_ = message.data();
    return;
  }
  handle_ = std::unique_ptr<pcap, void (*)(pcap*)>(handle, closeHandle);
  link_type_ = pcap_datalink(handle);
  swapped_ = pcap_is_swapped(handle) == 1;
  if (!takenApart(link_type_)) {
    error_ = PcapError::kUnsupportedLinkType;
    const char* name = pcap_datalink_val_to_name(link_type_);
    detail_ =
        "link type " + std::to_string(link_type_) + (name != nullptr ? std::string(" (") + name + ")" : "");
  }
}

std::string PcapReader::errorText() const
{
  return detail_.empty() ? std::string(toString(error_)) : std::string(toString(error_)) + ": " + detail_;
}

PcapRecord PcapReader::next(UdpDatagram& datagram)
{
  if (error_ != PcapError::kNone) {
    return PcapRecord::kEndOfFile;
  }
  if (finished_) {
    return finished_result_;
  }
  pcap_pkthdr* header = nullptr;
  const u_char* data = nullptr;
  const int read = pcap_next_ex(handle_.get(), &header, &data);
  if (read != 1) {
    // -2: the last record was read; -1: the file ends inside a record, or its length fields are absurd
    // (libpcap refuses a record longer than the snap length): nothing after it can be trusted.
    finished_ = true;
    finished_result_ = read == PCAP_ERROR_BREAK ? PcapRecord::kEndOfFile : PcapRecord::kTruncatedFile;
    return finished_result_;
  }
  if (header->caplen > kMaximumRecordLength) {
    finished_ = true;
    finished_result_ = PcapRecord::kTruncatedFile;
    return finished_result_;
  }
  datagram = UdpDatagram{};
  datagram.capture_time_us = static_cast<std::int64_t>(header->ts.tv_sec) * 1'000'000 +
                             static_cast<std::int64_t>(header->ts.tv_usec) / 1000;  // nanoseconds here
  return parseFrame(link_type_, common::ByteView(data, header->caplen), header->len, datagram);
}

PcapRecord parseFrame(int link_type, common::ByteView frame, std::uint32_t original_length,
                      UdpDatagram& datagram)
{
  const std::uint8_t* bytes = frame.data();
  switch (link_type) {
    case DLT_EN10MB:
      return parseEthernetFrame(frame, original_length, datagram);
    case DLT_LINUX_SLL:
      return parseAfterHeader(
          frame, original_length, kSllHeaderSize,
          announcedBy(frame.size() >= kSllHeaderSize && readUint16Be(bytes + 14) == kEtherTypeIpv4),
          datagram);
    case DLT_LINUX_SLL2:
      return parseAfterHeader(
          frame, original_length, kSll2HeaderSize,
          announcedBy(frame.size() >= kSll2HeaderSize && readUint16Be(bytes) == kEtherTypeIpv4), datagram);
    case DLT_RAW:
      return parseAfterHeader(frame, original_length, 0, Announced::kAnyIp, datagram);
    case DLT_IPV4:
      return parseAfterHeader(frame, original_length, 0, Announced::kIpv4, datagram);
    case DLT_NULL:
      // The capturing host's byte order: AF_INET is 2 either way round.
      return parseAfterHeader(
          frame, original_length, kLoopbackHeaderSize,
          announcedBy(frame.size() >= kLoopbackHeaderSize && (readUint32Le(bytes) == kAddressFamilyInet ||
                                                              readUint32Be(bytes) == kAddressFamilyInet)),
          datagram);
    case DLT_LOOP:
      return parseAfterHeader(
          frame, original_length, kLoopbackHeaderSize,
          announcedBy(frame.size() >= kLoopbackHeaderSize && readUint32Be(bytes) == kAddressFamilyInet),
          datagram);
    default:
      return PcapRecord::kNotIpv4Udp;
  }
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
  return parseIpv4Packet(common::ByteView(bytes + offset, frame.size() - offset),
                         frame.size() < original_length, Announced::kIpv4, datagram);
}

}  // namespace ifar::velodyne
