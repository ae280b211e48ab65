#pragma once
// A reader for capture files, read through libpcap: classic pcap (either byte order, microsecond or
// nanosecond timestamps) and pcapng, as Wireshark, tcpdump and dumpcap write them. It yields the UDP
// payloads of IPv4 datagrams from frames of these link types: Ethernet (with an optional 802.1Q tag),
// Linux cooked captures (SLL and SLL2, `tcpdump -i any`), raw IPv4 and BSD loopback. Records that are not
// IPv4/UDP are reported and skipped; a file that ends inside a record (or whose next record cannot be
// read) is reported as truncated. libpcap stays inside pcap_reader.cpp.

#include <cstdint>
#include <cstdio>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "common/span.hpp"

struct pcap;  // libpcap's handle (pcap_t), known only to pcap_reader.cpp

namespace ifar::velodyne {

/// Problem with the file as a whole; reading is impossible unless kNone.
enum class PcapError : std::uint8_t {
  kNone,
  kCannotOpen,           // the file does not exist or cannot be read
  kTruncatedHeader,      // shorter than a capture file's header (24 bytes)
  kBadMagic,             // neither a pcap nor a pcapng file
  kUnsupportedLinkType,  // frames of a link type this reader does not take apart
  kUnreadable,           // libpcap refuses the file (errorText() says why)
};

/// Outcome of reading one record.
enum class PcapRecord : std::uint8_t {
  kUdpDatagram,     // the datagram was filled in
  kNotIpv4Udp,      // ARP, IPv6, TCP, ...: skipped
  kIpv4Fragment,    // a fragment of a larger datagram (not reassembled): skipped
  kMalformedFrame,  // lengths or header fields inconsistent: skipped
  kCapturedShort,   // the capture's snap length cut the datagram: skipped
  kTruncatedFile,   // the file ends inside a record: no further records
  kEndOfFile,       // no further records
};

const char* toString(PcapError error);
const char* toString(PcapRecord record);

struct UdpDatagram {
  std::int64_t capture_time_us = 0;  // record timestamp, microseconds since the Unix epoch
  std::uint32_t source_address = 0;  // IPv4, host byte order
  std::uint32_t destination_address = 0;
  std::uint16_t source_port = 0;
  std::uint16_t destination_port = 0;
  common::ByteView payload;  // valid until the next call to next() or the reader's destruction
};

class PcapReader {
 public:
  /// Opens a file; check error() before reading.
  static PcapReader open(const std::string& path);

  /// Reads from any stream (e.g. an std::istringstream in tests and fuzzers); takes ownership and reads
  /// all of it at once.
  explicit PcapReader(std::unique_ptr<std::istream> stream);

  ~PcapReader();
  PcapReader(PcapReader&& other) noexcept;
  PcapReader& operator=(PcapReader&& other) noexcept;
  PcapReader(const PcapReader&) = delete;
  PcapReader& operator=(const PcapReader&) = delete;

  PcapError error() const { return error_; }
  /// What is wrong with the file, in words: toString(error()) and, where libpcap said more, its words.
  std::string errorText() const;
  /// The link type of the file's frames (of its first interface, for pcapng), as libpcap's DLT_ value:
  /// 1 Ethernet, 113 and 276 Linux cooked, 12 raw IP (LINKTYPE_RAW 101 in the file), 228 IPv4, 0 and 108
  /// loopback.
  int linkType() const { return link_type_; }
  bool swappedByteOrder() const { return swapped_; }

  /// Reads the next record. After kTruncatedFile or kEndOfFile (or with error() set) it keeps
  /// returning the same value.
  PcapRecord next(UdpDatagram& datagram);

 private:
  explicit PcapReader(PcapError error) : error_(error) {}
  /// Checks the first bytes (size and magic number), then hands `file` to libpcap; closes it on failure.
  void openWith(std::FILE* file, const std::vector<std::uint8_t>& first_bytes);

  std::vector<char> memory_;  // the stream's bytes, read by libpcap through fmemopen
  std::unique_ptr<pcap, void (*)(pcap*)> handle_{nullptr, nullptr};
  PcapError error_ = PcapError::kNone;
  std::string detail_;  // libpcap's words for kUnreadable
  int link_type_ = -1;
  bool swapped_ = false;
  bool finished_ = false;
  PcapRecord finished_result_ = PcapRecord::kEndOfFile;
};

/// Finds the UDP payload inside one frame of `link_type` (a DLT_ value, as linkType()). Fills every field
/// of `datagram` except capture_time_us. `original_length` is the frame's length on the wire.
PcapRecord parseFrame(int link_type, common::ByteView frame, std::uint32_t original_length,
                      UdpDatagram& datagram);

/// parseFrame for an Ethernet frame (an optional 802.1Q tag is allowed).
PcapRecord parseEthernetFrame(common::ByteView frame, std::uint32_t original_length, UdpDatagram& datagram);

}  // namespace ifar::velodyne
