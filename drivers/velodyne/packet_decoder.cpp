#include "drivers/velodyne/packet_decoder.hpp"

#include <array>
#include <cmath>

#include "common/geometry/angle.hpp"

namespace ifar::velodyne {
namespace {

constexpr double kRadiansPerAzimuthUnit = geometry::kPi / 18000.0;
constexpr double kUnitsPerRevolution = kAzimuthUnitsPerRevolution;

struct LaserTrigonometry {
  std::array<double, kLasers> cos_elevation{};
  std::array<double, kLasers> sin_elevation{};
};

LaserTrigonometry makeLaserTrigonometry()
{
  LaserTrigonometry table;
  for (std::size_t laser = 0; laser < kLasers; ++laser) {
    const double radians = geometry::radiansFromDegrees(kLaserElevationDegrees[laser]);
    table.cos_elevation[laser] = std::cos(radians);
    table.sin_elevation[laser] = std::sin(radians);
  }
  return table;
}

// Computed once, never modified: the elevation of each laser is fixed by the hardware.
const LaserTrigonometry& laserTrigonometry()
{
  static const LaserTrigonometry table = makeLaserTrigonometry();
  return table;
}

/// Forward distance from `from` to `to` in azimuth units, in [0, 36000).
double azimuthStep(std::uint16_t from, std::uint16_t to)
{
  const int step = static_cast<int>(to) - static_cast<int>(from);
  return step < 0 ? step + kUnitsPerRevolution : step;
}

/// Azimuth of the second firing of every firing block, in units of 0.01 degree, wrapped into [0, 36000).
double secondFiringOffset(const std::array<std::uint16_t, kBlocksPerPacket>& azimuths,
                          std::size_t blocks_per_firing, AzimuthInterpolation interpolation)
{
  const std::size_t last_firing_block = kBlocksPerPacket - blocks_per_firing;
  if (interpolation == AzimuthInterpolation::kVlpGrabber) {
    return azimuthStep(azimuths[0], azimuths[blocks_per_firing]) / 2.0;
  }
  const std::size_t firing_blocks = kBlocksPerPacket / blocks_per_firing;  // whole firings per packet
  const double step_per_firing =
      azimuthStep(azimuths[0], azimuths[last_firing_block]) / static_cast<double>(firing_blocks - 1);
  return step_per_firing / 2.0;
}

double wrapAzimuth(double units)
{
  return units >= kUnitsPerRevolution ? units - kUnitsPerRevolution : units;
}

}  // namespace

DecodeResult decodePacket(common::ByteView payload, std::vector<Point>& points, const DecoderOptions& options)
{
  DecodeResult result;
  result.info = inspectPacket(payload, options.sensor_model);
  if (result.info.status != PacketStatus::kOk) {
    return result;
  }
  const std::uint8_t* bytes = payload.data();
  const bool dual = result.info.return_mode == ReturnMode::kDual;
  const std::size_t blocks_per_firing = dual ? 2 : 1;

  std::array<std::uint16_t, kBlocksPerPacket> azimuths{};
  for (std::size_t block = 0; block < kBlocksPerPacket; ++block) {
    azimuths[block] = readUint16Le(bytes + block * kBlockSize + kBlockAzimuthOffset);
  }
  const double half_step = secondFiringOffset(azimuths, blocks_per_firing, options.interpolation);
  const LaserTrigonometry& trigonometry = laserTrigonometry();
  const ReturnType single_type =
      result.info.return_mode == ReturnMode::kLast ? ReturnType::kLast : ReturnType::kStrongest;

  const std::size_t first_new = points.size();
  points.reserve(first_new + kBlocksPerPacket * kReturnsPerBlock);
  for (std::size_t block = 0; block < kBlocksPerPacket; ++block) {
    const std::uint8_t* block_bytes = bytes + block * kBlockSize;
    // Dual return: even blocks hold the last return, odd blocks the strongest, of the same firings.
    const std::uint8_t return_index = dual ? static_cast<std::uint8_t>(block % 2) : 0;
    const ReturnType return_type =
        !dual ? single_type : (block % 2 == 0 ? ReturnType::kLast : ReturnType::kStrongest);
    const std::size_t firing_block_index = block / blocks_per_firing;  // blocks of one firing share it
    const double firing_block = static_cast<double>(firing_block_index);

    for (std::size_t firing = 0; firing < kFiringsPerBlock; ++firing) {
      double azimuth_units = azimuths[block];
      if (firing == 1) {
        azimuth_units = wrapAzimuth(azimuth_units + half_step);
        if (options.interpolation == AzimuthInterpolation::kVlpGrabber) {
          azimuth_units = std::trunc(azimuth_units);
        }
      }
      const double azimuth_radians = azimuth_units * kRadiansPerAzimuthUnit;
      const double cos_azimuth = std::cos(azimuth_radians);
      const double sin_azimuth = std::sin(azimuth_radians);
      const auto azimuth_degrees = static_cast<float>(azimuth_units / 100.0);
      const double firing_start_us =
          (firing_block * static_cast<double>(kFiringsPerBlock) + static_cast<double>(firing)) *
          kFiringSequenceMicroseconds;

      const std::uint8_t* returns = block_bytes + kBlockReturnsOffset + firing * kLasers * kReturnSize;
      for (std::size_t laser = 0; laser < kLasers; ++laser) {
        const std::uint8_t* raw = returns + laser * kReturnSize;
        const std::uint16_t raw_distance = readUint16Le(raw);
        if (raw_distance == 0 && !options.keep_no_return) {
          continue;
        }
        const double distance = raw_distance * kDistanceUnitMetres;
        const double horizontal = distance * trigonometry.cos_elevation[laser];
        Point point;
        // Azimuth turns clockwise from +x seen from above, so y (left) is -sin.
        point.x = static_cast<float>(horizontal * cos_azimuth);
        point.y = static_cast<float>(-horizontal * sin_azimuth);
        point.z = static_cast<float>(distance * trigonometry.sin_elevation[laser]);
        point.distance = static_cast<float>(distance);
        point.azimuth_degrees = azimuth_degrees;
        point.time_offset_us =
            static_cast<float>(firing_start_us + static_cast<double>(laser) * kLaserIntervalMicroseconds);
        point.reflectivity = raw[2];
        point.laser = static_cast<std::uint8_t>(laser);
        point.ring = kLaserRing[laser];
        point.return_index = return_index;
        point.return_type = return_type;
        points.push_back(point);
      }
    }
  }
  result.points_added = points.size() - first_new;
  return result;
}

}  // namespace ifar::velodyne
