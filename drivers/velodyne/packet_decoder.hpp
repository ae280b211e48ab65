#pragma once
// VLP-16 data packet -> points, for strongest, last and dual return packets.
//
// Azimuth: every block carries the azimuth of its first firing. The second firing happens half a block
// later, so its azimuth is the block azimuth plus half the packet's mean step between firing blocks
// (consecutive blocks in single return mode, block pairs in dual mode), wrapped into [0, 360). The mean
// over the packet smooths the encoder's +-0.02 degree jitter between blocks. All 16 lasers of a firing
// share the firing's azimuth (as PCL's VLPGrabber does); each point's time offset still follows the
// timing table, so a consumer can refine the azimuth per laser from the rotation rate.
// Time offset of laser l in firing f of block b: (b' * 2 + f) * 55.296 us + l * 2.304 us, where b' = b in
// single return mode and b / 2 in dual mode (the two blocks of a pair share firing times).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/span.hpp"
#include "drivers/velodyne/packet_format.hpp"
#include "drivers/velodyne/point.hpp"

namespace ifar::velodyne {

enum class AzimuthInterpolation : std::uint8_t {
  kPacketMeanStep,  // default: half the mean block step of the packet (see above)
  kVlpGrabber,      // as PCL 1.13 VLPGrabber: half the step between the first two firing blocks, then
                    // truncated to whole 0.01 degree; only for point-for-point checks against PCL
};

struct DecoderOptions {
  bool keep_no_return = false;  // keep distance-0 returns ("no return") as points at the origin
  AzimuthInterpolation interpolation = AzimuthInterpolation::kPacketMeanStep;
  SensorModel sensor_model = SensorModel::kAuto;  // kVlp16: any product byte is decoded (see inspectPacket)
};

struct DecodeResult {
  PacketInfo info;  // status, return mode and device timestamp
  std::size_t points_added = 0;
};

/// Validates `payload` (see inspectPacket) and, when valid, appends its points to `points` in packet
/// order (block, firing, laser). An invalid packet appends nothing. Never reads outside `payload`.
DecodeResult decodePacket(common::ByteView payload, std::vector<Point>& points,
                          const DecoderOptions& options = {});

}  // namespace ifar::velodyne
