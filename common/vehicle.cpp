#include "common/vehicle.hpp"

namespace ifar::common {
namespace {

double positive(const ConfigNode& node, const std::string& key)
{
  const double value = node.required<double>(key);
  if (!(value > 0.0)) {
    node.fail(key, "must be greater than zero, got " + std::to_string(value));
  }
  return value;
}

}  // namespace

VehicleSettings loadVehicleSettings(const ConfigNode& node)
{
  VehicleSettings settings;
  settings.length_m = positive(node, "length_m");
  settings.width_m = positive(node, "width_m");
  settings.wheel_track_m = positive(node, "wheel_track_m");
  settings.wheel_radius_m = positive(node, "wheel_radius_m");
  settings.mass_kg = positive(node, "mass_kg");
  settings.traction_coefficient = positive(node, "traction_coefficient");
  settings.max_linear_velocity = positive(node, "max_linear_velocity");
  settings.max_angular_velocity = positive(node, "max_angular_velocity");
  settings.max_linear_acceleration = positive(node, "max_linear_acceleration");
  settings.max_angular_acceleration = positive(node, "max_angular_acceleration");
  settings.bumper_width_m = positive(node, "bumper_width_m");
  settings.bumper_friction = positive(node, "bumper_friction");
  settings.lidar_height_m = positive(node, "lidar_height_m");
  settings.lidar_x_m = node.required<double>("lidar_x_m");
  settings.force_sensor_range_n = positive(node, "force_sensor_range_n");
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::common
