#include "common/vehicle.hpp"

namespace ifar::common {
VehicleSettings loadVehicleSettings(const ConfigNode& node)
{
  VehicleSettings settings;
  settings.length_m = node.requiredPositive("length_m");
  settings.width_m = node.requiredPositive("width_m");
  settings.wheel_track_m = node.requiredPositive("wheel_track_m");
  settings.wheel_radius_m = node.requiredPositive("wheel_radius_m");
  settings.mass_kg = node.requiredPositive("mass_kg");
  settings.traction_coefficient = node.requiredPositive("traction_coefficient");
  settings.max_linear_velocity = node.requiredPositive("max_linear_velocity");
  settings.max_angular_velocity = node.requiredPositive("max_angular_velocity");
  settings.max_linear_acceleration = node.requiredPositive("max_linear_acceleration");
  settings.max_angular_acceleration = node.requiredPositive("max_angular_acceleration");
  settings.bumper_width_m = node.requiredPositive("bumper_width_m");
  settings.bumper_friction = node.requiredPositive("bumper_friction");
  settings.lidar_height_m = node.requiredPositive("lidar_height_m");
  settings.lidar_x_m = node.required<double>("lidar_x_m");
  settings.force_sensor_range_n = node.requiredPositive("force_sensor_range_n");
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::common
