#include <cmath>
#include <string>

#include "executive/obstacles/local_obstacles.hpp"

namespace ifar::executive {

ObstacleSettings loadObstacleSettings(const common::ConfigNode& node)
{
  ObstacleSettings settings;
  settings.packet_channel = node.required<std::string>("packet_channel");
  if (settings.packet_channel.empty()) {
    node.fail("packet_channel", "must name an LCM channel");
  }
  settings.ground_clearance_m = node.required<double>("ground_clearance_m");
  if (!std::isfinite(settings.ground_clearance_m)) {
    node.fail("ground_clearance_m", "must be a finite height in metres");
  }
  settings.max_height_m = node.requiredPositive("max_height_m");
  if (settings.max_height_m <= settings.ground_clearance_m) {
    node.fail("max_height_m", "must be above ground_clearance_m (" +
                                  std::to_string(settings.ground_clearance_m) + "), got " +
                                  std::to_string(settings.max_height_m));
  }
  settings.min_range_m = node.required<double>("min_range_m");
  if (!(settings.min_range_m >= 0.0)) {
    node.fail("min_range_m", "must be zero or more, got " + std::to_string(settings.min_range_m));
  }
  settings.max_range_m = node.requiredPositive("max_range_m");
  if (settings.max_range_m <= settings.min_range_m) {
    node.fail("max_range_m", "must be above min_range_m (" + std::to_string(settings.min_range_m) +
                                 "), got " + std::to_string(settings.max_range_m));
  }
  settings.keep_s = node.requiredPositive("keep_s");
  if (settings.keep_s > 2.0) {
    // The ring is sized for keep_s of packets; seconds of lidar would also smear a moving obstacle.
    node.fail("keep_s", "must be at most 2 s, got " + std::to_string(settings.keep_s));
  }
  settings.movable_reflectivity_threshold = node.required<int>("movable_reflectivity_threshold");
  if (settings.movable_reflectivity_threshold < 0 || settings.movable_reflectivity_threshold > 256) {
    node.fail("movable_reflectivity_threshold", "must be within 0..256 (256: nothing is movable), got " +
                                                    std::to_string(settings.movable_reflectivity_threshold));
  }
  settings.cell_m = node.required<double>("cell_m");
  if (!(settings.cell_m >= 0.0) || !std::isfinite(settings.cell_m)) {
    node.fail("cell_m", "must be zero (keep every return) or a positive size in metres, got " +
                            std::to_string(settings.cell_m));
  }
  node.rejectUnknownKeys();
  // The executive's loader accepts this whole section, so an unknown key here is caught here.
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::executive
