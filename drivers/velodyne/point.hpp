#pragma once
// One decoded VLP-16 return.

#include <cstdint>

namespace ifar::velodyne {

/// Which echo a point is in dual return mode (and which mode a single-return packet was in).
enum class ReturnType : std::uint8_t {
  kStrongest,
  kLast,
};

/// A return in the sensor frame: x forward (azimuth 0), y left, z up (right-handed, ROS REP 103).
/// The VLP-16 azimuth turns clockwise seen from above, so azimuth 90 degrees points along -y.
struct Point {
  float x = 0.0F;                 // metres
  float y = 0.0F;                 // metres
  float z = 0.0F;                 // metres
  float distance = 0.0F;          // metres, along the beam
  float azimuth_degrees = 0.0F;   // [0, 360): block azimuth, interpolated for the second firing
  float time_offset_us = 0.0F;    // microseconds after the packet's timestamp (firing timing table)
  std::uint8_t reflectivity = 0;  // calibrated reflectivity byte as sent (0..100 diffuse, 101..255 retro)
  std::uint8_t laser = 0;         // laser index in firing order, 0..15
  std::uint8_t ring = 0;          // 0 = lowest beam (-15 degrees) .. 15 = highest (+15 degrees)
  std::uint8_t return_index = 0;  // 0 = only return (single modes) or the last return of a dual pair,
                                  // 1 = strongest return of a dual pair
  ReturnType return_type = ReturnType::kStrongest;
};

}  // namespace ifar::velodyne
