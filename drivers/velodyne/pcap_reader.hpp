#pragma once
// A reader for classic pcap capture files (not pcapng) holding Ethernet frames, which yields the UDP
// payloads of IPv4 datagrams. Both byte orders and both time resolutions (microsecond magic 0xA1B2C3D4,
// nanosecond magic 0xA1B23C4D) are accepted. Records that are not IPv4/UDP are reported and skipped; a
// file that ends inside a record is reported as truncated.

#include <cstdint>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "common/span.hpp"

namespace ifar::velodyne {

/// Problem with the file as a whole; reading is impossible unless kNone.
enum class PcapError : std::uint8_t {
  kNone,
  kCannotOpen,           // the file does not exist or cannot be read
  kTruncatedHeader,      // shorter than the 24-byte global header
  kBadMagic,             // not a classic pcap file (pcapng and others are not supported)
  kUnsupportedLinkType,  // link type is not Ethernet (1)
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

  /// Reads from any stream (e.g. an std::istringstream in tests and fuzzers); takes ownership.
  explicit PcapReader(std::unique_ptr<std::istream> stream);

  PcapError error() const { return error_; }
  bool nanosecondTimestamps() const { return nanosecond_; }
  bool swappedByteOrder() const { return swapped_; }

  /// Reads the next record. After kTruncatedFile or kEndOfFile (or with error() set) it keeps
  /// returning the same value.
  PcapRecord next(UdpDatagram& datagram);

 private:
  explicit PcapReader(PcapError error) : error_(error) {}
  void readGlobalHeader();
  std::uint32_t fileUint32(const std::uint8_t* bytes) const;

  std::unique_ptr<std::istream> stream_;
  PcapError error_ = PcapError::kNone;
  bool swapped_ = false;
  bool nanosecond_ = false;
  bool finished_ = false;
  PcapRecord finished_result_ = PcapRecord::kEndOfFile;
  std::vector<std::uint8_t> record_;
};

/// Finds the UDP payload inside one Ethernet frame (an optional 802.1Q tag is allowed). Fills every field
/// of `datagram` except capture_time_us. `original_length` is the frame's length on the wire.
PcapRecord parseEthernetFrame(common::ByteView frame, std::uint32_t original_length, UdpDatagram& datagram);

}  // namespace ifar::velodyne
