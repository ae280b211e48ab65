#include "drivers/velodyne/packet_format.hpp"

namespace ifar::velodyne {

const char* toString(PacketStatus status)
{
  switch (status) {
    case PacketStatus::kOk:
      return "ok";
    case PacketStatus::kWrongSize:
      return "wrong size";
    case PacketStatus::kBadBlockMarker:
      return "bad block marker";
    case PacketStatus::kAzimuthOutOfRange:
      return "azimuth out of range";
    case PacketStatus::kUnknownProduct:
      return "unknown product";
    case PacketStatus::kUnknownReturnMode:
      return "unknown return mode";
  }
  return "unknown status";
}

PacketInfo inspectPacket(common::ByteView payload)
{
  PacketInfo info;
  if (payload.size() != kDataPacketSize) {
    info.status = PacketStatus::kWrongSize;
    return info;
  }
  const std::uint8_t* bytes = payload.data();
  for (std::size_t block = 0; block < kBlocksPerPacket; ++block) {
    const std::uint8_t* block_bytes = bytes + block * kBlockSize;
    if (block_bytes[kBlockMarkerOffset] != kBlockMarkerFirst ||
        block_bytes[kBlockMarkerOffset + 1] != kBlockMarkerSecond) {
      info.status = PacketStatus::kBadBlockMarker;
      return info;
    }
    if (readUint16Le(block_bytes + kBlockAzimuthOffset) >= kAzimuthUnitsPerRevolution) {
      info.status = PacketStatus::kAzimuthOutOfRange;
      return info;
    }
  }
  if (bytes[kProductIdOffset] != static_cast<std::uint8_t>(ProductId::kVlp16)) {
    info.status = PacketStatus::kUnknownProduct;
    return info;
  }
  const std::uint8_t mode = bytes[kReturnModeOffset];
  if (mode != static_cast<std::uint8_t>(ReturnMode::kStrongest) &&
      mode != static_cast<std::uint8_t>(ReturnMode::kLast) &&
      mode != static_cast<std::uint8_t>(ReturnMode::kDual)) {
    info.status = PacketStatus::kUnknownReturnMode;
    return info;
  }
  info.return_mode = static_cast<ReturnMode>(mode);
  info.device_time_past_hour = readUint32Le(bytes + kTimestampOffset);
  info.status = PacketStatus::kOk;
  return info;
}

}  // namespace ifar::velodyne
