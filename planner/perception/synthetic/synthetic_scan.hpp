#pragma once
// Synthetic lidar scans of known worlds, for tests and benchmarks: obstacle faces sampled on a
// regular grid, and a VLP-16 revolution ray-cast against prism obstacles, a flat ground and an
// optional ceiling.

#include <optional>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/perception/sensor_point.hpp"

namespace ifar::perception::synthetic {

/// A vertical prism standing on the ground (z = 0): footprint in the world frame, height, and the
/// reflectivity its faces return.
struct PrismObstacle {
  geometry::Polygon footprint;
  double height_m = 1.0;
  float reflectivity = 20.0F;
};

/// An axis-aligned box footprint from its centre and side lengths.
geometry::Polygon boxFootprint(double centre_x, double centre_y, double size_x, double size_y);

/// Points on every vertical face of every obstacle, `spacing_m` apart along the face (end points
/// included) at each of `heights_m`, expressed in the sensor frame of `sensor_to_world`. Time 0.
std::vector<SensorPoint> sampleObstacleFaces(const std::vector<PrismObstacle>& obstacles,
                                             const std::vector<double>& heights_m, double spacing_m,
                                             const Eigen::Isometry3d& sensor_to_world);

struct RevolutionSettings {
  double azimuth_step_deg = 0.2;
  double duration_s = 0.1;
  double max_range_m = 100.0;
  std::optional<double> ceiling_height_m;  // a flat ceiling returns upward beams (indoor rooms)
};

/// One revolution of the 16 VLP-16 lasers (-15 .. 15 degrees, 2 degree steps) from a level sensor at
/// `sensor_to_world` (only its position and yaw are used), in the sensor frame, time increasing with
/// azimuth over `duration_s`. Beams that hit nothing within max_range_m give no point.
std::vector<SensorPoint> simulateRevolution(const std::vector<PrismObstacle>& obstacles,
                                            const Eigen::Isometry3d& sensor_to_world,
                                            const RevolutionSettings& settings);

/// A 32 m x 32 m walled room (walls 0.2 m thick, 2.5 m high, ceiling at 3 m) with eight boxes,
/// three of them movable (reflectivity 200), centred on the world origin.
std::vector<PrismObstacle> roomWithBoxes();

}  // namespace ifar::perception::synthetic
