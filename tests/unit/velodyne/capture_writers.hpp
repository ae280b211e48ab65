#pragma once
// Capture files written byte by byte, independent of libpcap and of the reader under test: classic pcap in
// either byte order, pcapng, and Linux cooked frames made from Ethernet ones.

#include <cstdint>
#include <string>
#include <vector>

namespace ifar::velodyne {

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

// Writes pcapng (one section, one interface, enhanced packet blocks), little-endian, independent of libpcap.
class PcapngWriter {
 public:
  explicit PcapngWriter(std::uint16_t link_type, bool nanosecond_resolution = false)
  {
    // Section header block: byte-order magic, version 1.0, section length unknown.
    block(0x0A0D0D0AU, {0x1A2B3C4DU, 0x00000001U, 0xFFFFFFFFU, 0xFFFFFFFFU});
    // Interface description block: link type, snap length, then (for nanoseconds) the if_tsresol option.
    std::vector<std::uint32_t> interface = {link_type, 262144};
    if (nanosecond_resolution) {
      interface.push_back(0x00010009U);  // option 9 (if_tsresol), length 1
      interface.push_back(9);            // 10^-9, padded to 4 bytes
      interface.push_back(0);            // end of options
    }
    block(0x00000001U, interface);
  }

  /// An enhanced packet block; `ticks` in the interface's resolution (microseconds unless nanoseconds).
  void packet(std::uint64_t ticks, const std::vector<std::uint8_t>& frame)
  {
    std::vector<std::uint32_t> words = {
        0, static_cast<std::uint32_t>(ticks >> 32), static_cast<std::uint32_t>(ticks),
        static_cast<std::uint32_t>(frame.size()), static_cast<std::uint32_t>(frame.size())};
    std::vector<std::uint8_t> padded = frame;
    padded.resize((frame.size() + 3) / 4 * 4, 0);
    for (std::size_t index = 0; index < padded.size(); index += 4) {
      words.push_back(static_cast<std::uint32_t>(padded[index]) |
                      (static_cast<std::uint32_t>(padded[index + 1]) << 8) |
                      (static_cast<std::uint32_t>(padded[index + 2]) << 16) |
                      (static_cast<std::uint32_t>(padded[index + 3]) << 24));
    }
    block(0x00000006U, words);
  }

  std::string text() const { return std::string(bytes_.begin(), bytes_.end()); }

 private:
  void put32(std::uint32_t value)
  {
    for (int shift = 0; shift < 32; shift += 8) {
      bytes_.push_back(static_cast<std::uint8_t>(value >> shift));
    }
  }
  void block(std::uint32_t type, const std::vector<std::uint32_t>& body)
  {
    const auto length = static_cast<std::uint32_t>(12 + 4 * body.size());
    put32(type);
    put32(length);
    for (const std::uint32_t word : body) {
      put32(word);
    }
    put32(length);
  }

  std::vector<std::uint8_t> bytes_;
};

/// `ethernet` (udpFrame's) with its 14-byte Ethernet header replaced by a Linux cooked capture header.
inline std::vector<std::uint8_t> cookedFrame(const std::vector<std::uint8_t>& ethernet, bool version_2)
{
  std::vector<std::uint8_t> header;
  if (version_2) {
    header = {0x08, 0x00, 0, 0, 0, 0, 0, 3, 0, 1, 0, 6, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0, 0};
  } else {
    header = {0, 0, 0, 1, 0, 6, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0, 0, 0x08, 0x00};
  }
  header.insert(header.end(), ethernet.begin() + 14, ethernet.end());
  return header;
}

}  // namespace ifar::velodyne
