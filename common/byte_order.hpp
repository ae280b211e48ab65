#pragma once
// Reading fixed-width integers from bytes in a stated byte order: LCM logs and pcap headers are
// big-endian, VLP-16 payloads and pcap records of little-endian captures little-endian. The caller
// checks the bounds.

#include <cstdint>

namespace ifar::common {

constexpr std::uint16_t readUint16Le(const std::uint8_t* bytes)
{
  return static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8));
}

constexpr std::uint32_t readUint32Le(const std::uint8_t* bytes)
{
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8U) |
         (static_cast<std::uint32_t>(bytes[2]) << 16U) | (static_cast<std::uint32_t>(bytes[3]) << 24U);
}

constexpr std::uint16_t readUint16Be(const std::uint8_t* bytes)
{
  return static_cast<std::uint16_t>((bytes[0] << 8) | bytes[1]);
}

constexpr std::uint32_t readUint32Be(const std::uint8_t* bytes)
{
  return (static_cast<std::uint32_t>(bytes[0]) << 24U) | (static_cast<std::uint32_t>(bytes[1]) << 16U) |
         (static_cast<std::uint32_t>(bytes[2]) << 8U) | static_cast<std::uint32_t>(bytes[3]);
}

constexpr std::uint64_t readUint64Be(const std::uint8_t* bytes)
{
  return (static_cast<std::uint64_t>(readUint32Be(bytes)) << 32U) | readUint32Be(bytes + 4);
}

}  // namespace ifar::common
