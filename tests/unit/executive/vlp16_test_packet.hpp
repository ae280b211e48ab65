#pragma once
// Hand-made VLP-16 data packets for the executive's obstacle tests: every return empty except the ones
// set, so a test knows exactly which points a packet holds.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drivers/velodyne/packet_format.hpp"

namespace ifar::executive::testing {

class TestPacket {
 public:
  /// Strongest-return VLP-16 packet; block b's azimuth is `first_azimuth` + 40 b (0.01 degree units,
  /// the 0.4 degree block step of a 10 Hz rotation), wrapped.
  explicit TestPacket(std::uint16_t first_azimuth = 0) : bytes_(velodyne::kDataPacketSize, 0)
  {
    for (std::size_t block = 0; block < velodyne::kBlocksPerPacket; ++block) {
      const std::size_t offset = block * velodyne::kBlockSize;
      bytes_[offset] = velodyne::kBlockMarkerFirst;
      bytes_[offset + 1] = velodyne::kBlockMarkerSecond;
      const auto azimuth =
          static_cast<std::uint16_t>((first_azimuth + 40 * block) % velodyne::kAzimuthUnitsPerRevolution);
      bytes_[offset + 2] = static_cast<std::uint8_t>(azimuth & 0xFF);
      bytes_[offset + 3] = static_cast<std::uint8_t>(azimuth >> 8);
    }
    bytes_[velodyne::kReturnModeOffset] = static_cast<std::uint8_t>(velodyne::ReturnMode::kStrongest);
    bytes_[velodyne::kProductIdOffset] = static_cast<std::uint8_t>(velodyne::ProductId::kVlp16);
  }

  /// Sets the return of `laser` in the first firing of `block`: distance in 2 mm units.
  TestPacket& set(std::size_t block, std::size_t laser, std::uint16_t distance_units,
                  std::uint8_t reflectivity)
  {
    const std::size_t offset =
        block * velodyne::kBlockSize + velodyne::kBlockReturnsOffset + laser * velodyne::kReturnSize;
    bytes_[offset] = static_cast<std::uint8_t>(distance_units & 0xFF);
    bytes_[offset + 1] = static_cast<std::uint8_t>(distance_units >> 8);
    bytes_[offset + 2] = reflectivity;
    return *this;
  }

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace ifar::executive::testing
