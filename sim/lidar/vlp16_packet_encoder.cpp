#include "sim/lidar/vlp16_packet_encoder.hpp"

namespace ifar::sim::lidar {
namespace {

void putUint16(Vlp16Packet& packet, std::size_t offset, std::uint16_t value)
{
  packet[offset] = static_cast<std::uint8_t>(value & 0xFFu);
  packet[offset + 1] = static_cast<std::uint8_t>(value >> 8);
}

void putFiring(Vlp16Packet& packet, std::size_t offset, const Vlp16Firing& firing)
{
  for (std::size_t laser = 0; laser < kVlp16Lasers; ++laser) {
    putUint16(packet, offset + 3 * laser, firing.distance_units[laser]);
    packet[offset + 3 * laser + 2] = firing.reflectivity[laser];
  }
}

}  // namespace

Vlp16Packet encodeVlp16Packet(const std::array<Vlp16Block, kVlp16BlocksPerPacket>& blocks,
                              std::uint32_t timestamp_microseconds_past_hour, std::uint8_t return_mode)
{
  constexpr std::size_t kBlockSize = 100;
  Vlp16Packet packet{};
  for (std::size_t block = 0; block < kVlp16BlocksPerPacket; ++block) {
    const std::size_t offset = block * kBlockSize;
    packet[offset] = 0xFF;
    packet[offset + 1] = 0xEE;
    putUint16(packet, offset + 2, static_cast<std::uint16_t>(blocks[block].azimuth_centidegrees % 36000));
    putFiring(packet, offset + 4, blocks[block].first);
    putFiring(packet, offset + 4 + 3 * kVlp16Lasers, blocks[block].second);
  }
  const std::size_t tail = kVlp16BlocksPerPacket * kBlockSize;
  for (std::size_t byte = 0; byte < 4; ++byte) {
    packet[tail + byte] = static_cast<std::uint8_t>((timestamp_microseconds_past_hour >> (8 * byte)) & 0xFFu);
  }
  packet[tail + 4] = return_mode;
  packet[tail + 5] = kVlp16ProductId;
  return packet;
}

}  // namespace ifar::sim::lidar
