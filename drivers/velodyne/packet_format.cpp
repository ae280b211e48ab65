#include "drivers/velodyne/packet_format.hpp"

#include <fmt/format.h>

namespace ifar::velodyne {
namespace {

std::string productText(std::uint8_t product_byte)
{
  const std::string name = productName(product_byte);
  return name.empty() ? fmt::format("0x{:02X}", product_byte)
                      : fmt::format("0x{:02X} ({})", product_byte, name);
}

}  // namespace

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

PacketInfo inspectPacket(common::ByteView payload, SensorModel model)
{
  PacketInfo info;
  if (payload.size() != kDataPacketSize) {
    info.status = PacketStatus::kWrongSize;
    return info;
  }
  const std::uint8_t* bytes = payload.data();
  info.product_byte = bytes[kProductIdOffset];
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
  // The firing layout is what decoding depends on; the product byte only says which layout to expect.
  // A configured model is the user's word for it, so the byte is then a label (e.g. a mislabelled capture).
  if (info.product_byte != static_cast<std::uint8_t>(ProductId::kVlp16)) {
    if (model == SensorModel::kAuto) {
      info.status = PacketStatus::kUnknownProduct;
      return info;
    }
    info.product_overridden = true;
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

const char* productName(std::uint8_t product_byte)
{
  switch (product_byte) {
    case static_cast<std::uint8_t>(ProductId::kHdl32e):
      return "HDL-32E";
    case static_cast<std::uint8_t>(ProductId::kVlp16):
      return "VLP-16";
    case static_cast<std::uint8_t>(ProductId::kVlp32c):
      return "VLP-32C";
    default:
      return "";
  }
}

std::string describeProblem(const PacketInfo& info)
{
  if (info.status == PacketStatus::kUnknownProduct) {
    return fmt::format(
        "product byte 0x{:02X} (expected 0x22, VLP-16); set sensor_model: VLP-16 to decode it anyway",
        info.product_byte);
  }
  return toString(info.status);
}

std::string overriddenProductWarning(std::uint8_t product_byte, SensorModel model)
{
  const char* configured = model == SensorModel::kVlp16 ? "VLP-16" : "auto";
  return fmt::format(
      "data packets carry product byte {}, not 0x22: decoding them as {} because sensor_model says so; if "
      "the "
      "sensor is not a {} its points are wrong",
      productText(product_byte), configured, configured);
}

}  // namespace ifar::velodyne
