#pragma once
// Encodes VLP-16 data packets byte for byte as the sensor sends them (PLATFORM.md): 12 blocks of
// 0xFF 0xEE, azimuth uint16 little-endian in 0.01 degree, 32 x (distance uint16 little-endian in 2 mm
// units, reflectivity uint8) with lasers 0-15 of the first firing then of the second; then the uint32
// little-endian timestamp in microseconds past the hour, the return mode and the product id.

#include <array>
#include <cstdint>

namespace ifar::sim::lidar {

constexpr std::size_t kVlp16PacketSize = 1206;
constexpr std::size_t kVlp16BlocksPerPacket = 12;
constexpr std::size_t kVlp16FiringsPerPacket = 24;
constexpr std::size_t kVlp16Lasers = 16;
constexpr std::uint8_t kVlp16StrongestReturn = 0x37;
constexpr std::uint8_t kVlp16ProductId = 0x22;
constexpr double kVlp16DistanceUnitM = 0.002;

using Vlp16Packet = std::array<std::uint8_t, kVlp16PacketSize>;

/// One firing sequence: the 16 lasers fired once.
struct Vlp16Firing {
  std::array<std::uint16_t, kVlp16Lasers> distance_units{};  // 2 mm units, 0 = no return
  std::array<std::uint8_t, kVlp16Lasers> reflectivity{};
};

/// A block holds two consecutive firings and the azimuth of the first one.
struct Vlp16Block {
  std::uint16_t azimuth_centidegrees = 0;  // 0..35999
  Vlp16Firing first;
  Vlp16Firing second;
};

Vlp16Packet encodeVlp16Packet(const std::array<Vlp16Block, kVlp16BlocksPerPacket>& blocks,
                              std::uint32_t timestamp_microseconds_past_hour,
                              std::uint8_t return_mode = kVlp16StrongestReturn);

}  // namespace ifar::sim::lidar
