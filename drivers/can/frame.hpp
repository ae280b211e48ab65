#pragma once
// One classic CAN frame as a value: what every CanBus sends and receives, independent of SocketCAN.

#include <array>
#include <cstdint>
#include <initializer_list>

#include "common/span.hpp"

namespace ifar::can {

/// Frame flag bits; the values match ifar::can_frame_t's FLAG_ constants so the LCM bridge copies them.
constexpr std::uint8_t kFlagExtended = 1;  // 29-bit identifier
constexpr std::uint8_t kFlagRemote = 2;    // remote transmission request
constexpr std::uint8_t kFlagError = 4;     // error frame: id holds the CAN_ERR_* class bits

constexpr std::uint32_t kStandardIdMask = 0x7FF;
constexpr std::uint32_t kExtendedIdMask = 0x1FFFFFFF;
constexpr std::uint8_t kMaxDataLength = 8;

struct Frame {
  std::uint32_t id = 0;                             // 11-bit or 29-bit identifier, without flag bits
  std::uint8_t flags = 0;                           // bitwise OR of the kFlag constants
  std::uint8_t dlc = 0;                             // data length, 0..8
  std::array<std::uint8_t, kMaxDataLength> data{};  // bytes at and after dlc are zero
  std::int64_t timestamp_us = 0;  // receive time (kernel timestamp where available), us since the epoch

  bool extended() const { return (flags & kFlagExtended) != 0; }
  bool remote() const { return (flags & kFlagRemote) != 0; }
  bool error() const { return (flags & kFlagError) != 0; }
  /// The first dlc bytes.
  common::ByteView payload() const { return common::ByteView(data.data(), dlc <= kMaxDataLength ? dlc : 0); }
};

/// A standard (11-bit) data frame with the given bytes (at most 8; more are ignored).
Frame makeFrame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes);
/// A data frame from a byte view (at most 8 bytes taken).
Frame makeFrame(std::uint32_t id, common::ByteView bytes, std::uint8_t flags = 0);

/// Same id, flags, dlc and payload (timestamps are not compared).
bool sameContent(const Frame& left, const Frame& right);

/// Little-endian field access used by every frame codec in the project.
inline std::uint16_t readU16Le(const std::uint8_t* bytes)
{
  return static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8));
}
inline std::uint32_t readU32Le(const std::uint8_t* bytes)
{
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
         (static_cast<std::uint32_t>(bytes[2]) << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
}
inline void writeU16Le(std::uint8_t* bytes, std::uint16_t value)
{
  bytes[0] = static_cast<std::uint8_t>(value & 0xFF);
  bytes[1] = static_cast<std::uint8_t>(value >> 8);
}
inline void writeU32Le(std::uint8_t* bytes, std::uint32_t value)
{
  for (int index = 0; index < 4; ++index) {
    bytes[index] = static_cast<std::uint8_t>((value >> (8 * index)) & 0xFF);
  }
}

}  // namespace ifar::can
