#pragma once
// Builds VLP-16 data packets byte by byte for tests, independent of the decoder's own code paths.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ifar::velodyne::testing {

class PacketBuilder {
 public:
  PacketBuilder() : bytes_(1206, 0)
  {
    for (std::size_t block = 0; block < 12; ++block) {
      bytes_[block * 100] = 0xFF;
      bytes_[block * 100 + 1] = 0xEE;
    }
    bytes_[1204] = 0x37;
    bytes_[1205] = 0x22;
  }

  PacketBuilder& azimuth(std::size_t block, std::uint16_t hundredths)
  {
    putUint16(block * 100 + 2, hundredths);
    return *this;
  }
  /// Azimuths start, start + step, ... for the 12 blocks (wrapping at 36000).
  PacketBuilder& azimuthRamp(std::uint16_t start, std::uint16_t step)
  {
    for (std::size_t block = 0; block < 12; ++block) {
      azimuth(block, static_cast<std::uint16_t>((start + block * step) % 36000));
    }
    return *this;
  }
  /// `channel` 0..31: lasers 0-15 of firing 1, then lasers 0-15 of firing 2.
  PacketBuilder& ret(std::size_t block, std::size_t channel, std::uint16_t distance_2mm,
                     std::uint8_t reflectivity)
  {
    const std::size_t offset = block * 100 + 4 + channel * 3;
    putUint16(offset, distance_2mm);
    bytes_[offset + 2] = reflectivity;
    return *this;
  }
  PacketBuilder& allReturns(std::uint16_t distance_2mm, std::uint8_t reflectivity)
  {
    for (std::size_t block = 0; block < 12; ++block) {
      for (std::size_t channel = 0; channel < 32; ++channel) {
        ret(block, channel, distance_2mm, reflectivity);
      }
    }
    return *this;
  }
  PacketBuilder& timestamp(std::uint32_t microseconds_past_hour)
  {
    for (std::size_t index = 0; index < 4; ++index) {
      bytes_[1200 + index] = static_cast<std::uint8_t>(microseconds_past_hour >> (8 * index));
    }
    return *this;
  }
  PacketBuilder& mode(std::uint8_t return_mode)
  {
    bytes_[1204] = return_mode;
    return *this;
  }
  PacketBuilder& product(std::uint8_t product_id)
  {
    bytes_[1205] = product_id;
    return *this;
  }
  PacketBuilder& byte(std::size_t offset, std::uint8_t value)
  {
    bytes_[offset] = value;
    return *this;
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  void putUint16(std::size_t offset, std::uint16_t value)
  {
    bytes_[offset] = static_cast<std::uint8_t>(value & 0xFF);
    bytes_[offset + 1] = static_cast<std::uint8_t>(value >> 8);
  }

  std::vector<std::uint8_t> bytes_;
};

}  // namespace ifar::velodyne::testing
