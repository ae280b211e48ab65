#pragma once
// The VLP-16 data packet layout (1206-byte UDP payload on port 2368) and its validation. Facts from the
// VLP-16 user manual: 12 blocks of 100 bytes (marker 0xFF 0xEE, azimuth uint16 LE in 0.01 degree, then
// 32 returns of distance uint16 LE in 2 mm units and reflectivity uint8: lasers 0-15 of firing 1, then
// lasers 0-15 of firing 2), a uint32 LE timestamp in microseconds past the hour, the return mode byte and
// the product byte.

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/byte_order.hpp"
#include "common/span.hpp"

namespace ifar::velodyne {

constexpr std::uint16_t kDataPort = 2368;
constexpr std::uint16_t kPositionPort = 8308;

constexpr std::size_t kDataPacketSize = 1206;
constexpr std::size_t kPositionPacketSize = 512;
constexpr std::size_t kBlocksPerPacket = 12;
constexpr std::size_t kBlockSize = 100;
constexpr std::size_t kLasers = 16;
constexpr std::size_t kFiringsPerBlock = 2;
constexpr std::size_t kReturnsPerBlock = kLasers * kFiringsPerBlock;
constexpr std::size_t kReturnSize = 3;  // distance uint16 LE + reflectivity uint8

// Byte offsets inside a data packet and inside one block.
constexpr std::size_t kBlockMarkerOffset = 0;   // 0xFF 0xEE
constexpr std::size_t kBlockAzimuthOffset = 2;  // uint16 LE, 0.01 degree
constexpr std::size_t kBlockReturnsOffset = 4;  // 32 x 3 bytes
constexpr std::size_t kTimestampOffset = 1200;  // uint32 LE, microseconds past the hour
constexpr std::size_t kReturnModeOffset = 1204;
constexpr std::size_t kProductIdOffset = 1205;

constexpr std::uint8_t kBlockMarkerFirst = 0xFF;
constexpr std::uint8_t kBlockMarkerSecond = 0xEE;
constexpr std::uint16_t kAzimuthUnitsPerRevolution = 36000;  // valid raw azimuths are 0 .. 35999
constexpr double kDistanceUnitMetres = 0.002;
constexpr std::uint32_t kMicrosecondsPerHour = 3'600'000'000U;

// Firing timing (manual, VLP-16 timing table): lasers fire 2.304 us apart; a firing sequence of 16
// lasers plus recharge lasts 55.296 us; a block holds two sequences (110.592 us).
constexpr double kLaserIntervalMicroseconds = 2.304;
constexpr double kFiringSequenceMicroseconds = 55.296;
constexpr double kBlockDurationMicroseconds = 2.0 * kFiringSequenceMicroseconds;

/// Vertical angle of each laser in firing order (laser index 0..15), degrees.
constexpr std::array<double, kLasers> kLaserElevationDegrees = {-15, 1, -13, 3,  -11, 5,  -9, 7,
                                                                -7,  9, -5,  11, -3,  13, -1, 15};
/// Ring of each laser: 0 is the lowest beam (-15 degrees), 15 the highest (+15 degrees).
constexpr std::array<std::uint8_t, kLasers> kLaserRing = {0, 8,  1, 9,  2, 10, 3, 11,
                                                          4, 12, 5, 13, 6, 14, 7, 15};

enum class ReturnMode : std::uint8_t {
  kStrongest = 0x37,
  kLast = 0x38,
  kDual = 0x39,
};

/// Product (model) bytes of Velodyne sensors that share this packet size; only the VLP-16 layout is decoded.
enum class ProductId : std::uint8_t {
  kHdl32e = 0x21,  // 32 lasers, one firing per block: another layout
  kVlp16 = 0x22,
  kVlp32c = 0x28,  // 32 lasers, one firing per block: another layout
};

/// The model of the sensor as the configuration states it (driver key `sensor_model`).
enum class SensorModel : std::uint8_t {
  kAuto,   // the product byte decides: only 0x22 (VLP-16) is decoded
  kVlp16,  // the user says it is a VLP-16: the product byte is only a label, any value is decoded as
           // VLP-16 (a capture or firmware that mislabels it); data from another model then gives wrong
           // points
};

/// Outcome of validating a data packet. Anything but kOk means the packet must be skipped.
enum class PacketStatus : std::uint8_t {
  kOk,
  kWrongSize,          // payload is not 1206 bytes (truncated or oversized)
  kBadBlockMarker,     // a block does not start with 0xFF 0xEE
  kAzimuthOutOfRange,  // a block azimuth is >= 36000 (0.01 degree units)
  kUnknownProduct,     // product byte is not 0x22 (VLP-16) and no sensor model is configured
  kUnknownReturnMode,  // return mode byte is not 0x37, 0x38 or 0x39
};

/// Stable lower-case name of a status, e.g. "wrong size", for logs and velodyne_status_t.last_error.
const char* toString(PacketStatus status);

/// Header facts of a validated packet.
struct PacketInfo {
  PacketStatus status = PacketStatus::kWrongSize;
  ReturnMode return_mode = ReturnMode::kStrongest;  // meaningful only when status is kOk
  std::uint32_t device_time_past_hour = 0;          // microseconds; meaningful only when status is kOk
  std::uint8_t product_byte = 0;                    // as sent; meaningful unless status is kWrongSize
  bool product_overridden = false;  // kOk only because the configured model overrode the product byte
};

/// Checks size, every block marker and azimuth, the product byte and the return mode, in that order;
/// the first problem found is the status. With `model` kVlp16 any product byte passes (and
/// product_overridden says when it was not 0x22). Never reads outside `payload`.
PacketInfo inspectPacket(common::ByteView payload, SensorModel model = SensorModel::kAuto);

/// The model a product byte names, e.g. "HDL-32E" for 0x21; "" for a byte ifar does not know.
const char* productName(std::uint8_t product_byte);

/// Why a packet was refused, for logs and velodyne_status_t.last_error: the status name, except for a
/// product byte, which is named with the one expected, e.g. "product byte 0x21 (expected 0x22, VLP-16);
/// set sensor_model: VLP-16 to decode it anyway".
std::string describeProblem(const PacketInfo& info);

/// The warning for data packets decoded as `model` although their product byte says otherwise, e.g.
/// "data packets carry product byte 0x21 (HDL-32E), not 0x22: decoding them as VLP-16 because
/// sensor_model says so; if the sensor is not a VLP-16 its points are wrong".
std::string overriddenProductWarning(std::uint8_t product_byte, SensorModel model);

/// Which overridden product bytes have been reported, so each is logged once rather than per packet.
class ProductOverrideNotices {
 public:
  /// True the first time `info` is a packet whose product byte was overridden with this byte.
  bool firstOverride(const PacketInfo& info)
  {
    if (!info.product_overridden || seen_.test(info.product_byte)) {
      return false;
    }
    seen_.set(info.product_byte);
    return true;
  }

 private:
  std::bitset<256> seen_;
};

/// Little-endian readers used by the codec (bounds are the caller's job).
using common::readUint16Le;
using common::readUint32Le;

}  // namespace ifar::velodyne
